#!/usr/bin/env bash
# Installs missing packages, then configures and builds hlr (Release, ccache when present) in build/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
jobs=$(nproc 2>/dev/null || echo 2)
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
# CGAL translation units need ~1.5 GiB each; nproc jobs fit in memory on a 2-core, 24 GiB machine.
cmake --build build -j "$jobs"
