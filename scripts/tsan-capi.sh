#!/usr/bin/env bash
# The C API's concurrency test under ThreadSanitizer: gab.h promises that
# calls on different handles may run in several threads at once
# (tests/capi/threads_test.cpp runs four at once, two of them with two
# threads of their own inside the library). Builds the library and the C
# API's tests with -fsanitize=thread in build-tsan/ (about 6 minutes on two
# cores) and fails on any report:
#   bash scripts/tsan-capi.sh
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build-tsan -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DGAB_SANITIZE_THREAD=ON \
  -DGAB_BUILD_APPS=OFF -DGAB_BUILD_PYTHON=OFF
cmake --build build-tsan -j2 --target gab_capi_tests
TSAN_OPTIONS="halt_on_error=1 second_deadlock_stack=1" \
  build-tsan/tests/gab_capi_tests --gtest_filter='ThreadsTest.*'
echo "tsan-capi: no data race reported"
