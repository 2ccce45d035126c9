#!/usr/bin/env bash
# The README's second command: builds the test suites in build/ (configured
# by scripts/setup-and-run.sh, which built only the library and the tool),
# then runs the whole suite. Arguments go to ctest (e.g. -R capi).
set -euo pipefail
cd "$(dirname "$0")/.."
if [ ! -f build/CMakeCache.txt ]; then
  echo "run-tests.sh: build/ is not configured: run scripts/setup-and-run.sh first" >&2
  exit 2
fi
cmake --build build -j2
ctest --test-dir build --output-on-failure -j2 "$@"
