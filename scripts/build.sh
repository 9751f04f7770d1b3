#!/usr/bin/env bash
# Installs missing packages, then configures and builds hlr (Release, ccache when present) in build/,
# and installs the Python module hlrdraw for Debian's /usr/bin/python3.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
jobs=$(nproc 2>/dev/null || echo 2)
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
# CGAL translation units need ~1.5 GiB each; nproc jobs fit in memory on a 2-core, 24 GiB machine.
cmake --build build -j "$jobs"
# hlrdraw (python/CMakeLists.txt) into /usr/local/lib/python3.X/dist-packages, where Debian's
# interpreter finds it from any folder: `/usr/bin/python3 -c "import hlrdraw"`.
sudo_cmd=()
[ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
"${sudo_cmd[@]}" cmake --install build --component python >/dev/null
