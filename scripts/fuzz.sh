#!/usr/bin/env bash
# Fuzzes every harness (fuzz/) with clang's libFuzzer, AddressSanitizer and UndefinedBehaviorSanitizer
# for FUZZ_SECONDS each (default 60; a soak run: FUZZ_SECONDS=3600), in build-fuzz/. A finding is
# written to build-fuzz/fuzz/findings/; copy it to fuzz/findings/HARNESS/ once it is fixed, so that
# the default test suite replays it from then on.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
seconds=${FUZZ_SECONDS:-60}
sanitize="-fsanitize=address,undefined -fno-sanitize-recover=undefined -fsanitize=fuzzer-no-link"
CC=clang CXX=clang++ cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DHLR_FUZZ=ON \
  -DHLR_FUZZ_SECONDS="$seconds" -DHLR_BUILD_BENCH=OFF -DCMAKE_CXX_FLAGS="$sanitize" >/dev/null
cmake --build build-fuzz -j "$(nproc 2>/dev/null || echo 2)" --target mesh_reader_fuzz polygons_fuzz draw_fuzz
ctest --test-dir build-fuzz -L fuzz --output-on-failure
