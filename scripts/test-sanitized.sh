#!/usr/bin/env bash
# The default test suite under AddressSanitizer and UndefinedBehaviorSanitizer, in build-sanitized/
# (a separate build with debug info, slower to build and to run than the default one).
# Extra arguments go to ctest (e.g. -L cli, or -E soak to change what runs).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake -S . -B build-sanitized -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DHLR_SANITIZE=ON -DHLR_BUILD_BENCH=OFF >/dev/null
cmake --build build-sanitized -j "$(nproc 2>/dev/null || echo 2)"
# tcmalloc and ASan both replace malloc: hlr is linked without tcmalloc in this build (app/CMakeLists.txt).
ASAN_OPTIONS=detect_leaks=0 UBSAN_OPTIONS=print_stacktrace=1 \
  ctest --test-dir build-sanitized --output-on-failure -j "$(nproc 2>/dev/null || echo 2)" -LE "soak|fuzz" "$@"
