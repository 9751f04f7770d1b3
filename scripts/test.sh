#!/usr/bin/env bash
# Quick start (2): install, build, and run the default test suite (everything but the soak label).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
jobs=$(nproc 2>/dev/null || echo 2)
ctest --test-dir build --output-on-failure -j "$jobs" -LE soak
