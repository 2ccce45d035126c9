#!/usr/bin/env bash
# Builds the progressive viewer: the decoder in WebAssembly (web/CMakeLists.txt,
# with emscripten) and the page around it.
#
#   bash scripts/build-web.sh OUTDIR
#
# OUTDIR gets index.html, viewer.js, decoder.js, worker.js, gab_web.js and
# gab_web.wasm: serve it over HTTP (a browser will not fetch the .wasm from
# file://), put .gab files beside it and open index.html?file=NAME.gab. The
# object files stay in OUTDIR/.build, so a second run rebuilds only what
# changed.
# Needs Debian's emscripten (apt-get install emscripten).
set -euo pipefail

if [ $# -ne 1 ]; then
  echo "usage: bash scripts/build-web.sh OUTDIR" >&2
  exit 2
fi
root="$(cd "$(dirname "$0")/.." && pwd)"
mkdir -p "$1"
out="$(cd "$1" && pwd)"
build="$out/.build"

for tool in emcmake emcc cmake ninja; do
  if ! command -v "$tool" >/dev/null 2>&1; then
    echo "build-web: $tool not found (apt-get install emscripten cmake ninja-build)" >&2
    exit 1
  fi
done
# Debian's emscripten finds acorn (a node module it runs) only through NODE_PATH.
export NODE_PATH="${NODE_PATH:+$NODE_PATH:}/usr/share/nodejs"

emcmake cmake -S "$root/web" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" -j "${GAB_WEB_JOBS:-2}"

cp "$build/gab_web.js" "$build/gab_web.wasm" "$out/"
cp "$root/web/index.html" "$root/web/viewer.js" "$root/web/decoder.js" "$root/web/worker.js" "$out/"
echo "build-web: $out/index.html (serve $out over HTTP, open index.html?file=NAME.gab)" >&2
