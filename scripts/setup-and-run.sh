#!/usr/bin/env bash
# One command from a fresh Debian machine: install what is missing, build
# gab (Release: the library and the tool; the tests build in the README's
# second command), install it (library, headers, the gab tool
# and the Python module) under GAB_PREFIX (default ~/.local, whose Python
# site directory python3 searches), fetch a real mesh from Debian's
# libcgal-demo, and run the main job on it (gab demo: compress / decompress).
set -euo pipefail
cd "$(dirname "$0")/.."

# Waits (bounded, GAB_APT_WAIT) while another process holds apt's lock.
bash scripts/apt-install.sh cmake ninja-build g++ libgtest-dev googletest libbenchmark-dev libtinyobjloader-dev \
  libcgal-demo python3-numpy

# Real meshes shipped by libcgal-demo; never committed to this repository.
if [ ! -f data/meshes/camel.off ]; then
  mkdir -p data
  tar xzf /usr/share/doc/libcgal-dev/data.tar.gz -C data --strip-components=1 data/meshes
fi

# The library and the tool only: the tests are configured here and built by
# the README's second command (scripts/run-tests.sh), most of a full build.
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DGAB_BUILD_TESTS=ON
cmake --build build -j2 --target gab_installable
# The doors: libgab + gab.h for C, the gab module for python3 (README).
prefix="${GAB_PREFIX:-$HOME/.local}"
cmake --install build --prefix "$prefix"

# The main job: compress the camel at several anchor counts, decode every
# file again, print the table, write the meshes to gab-demo/.
./build/apps/gab demo

# Last, where the user reads it: what to add to the shell so `gab` and
# `import gab` find the install (nothing when they already do).
site_dir="$(grep -m1 '^GAB_PYTHON_INSTALL_DIR:' build/CMakeCache.txt | cut -d= -f2 || true)"
bash scripts/install-hints.sh "$prefix" "${site_dir:+$prefix/$site_dir}"
