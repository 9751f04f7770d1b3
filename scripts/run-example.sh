#!/usr/bin/env bash
# Quick start (1): install, build, and run the main job on a bundled part: the engineering drawing of
# fixtures/parts/anchor.off in the iso view, visible lines solid and hidden lines dashed, as an A4
# sheet (out/anchor_iso.svg, open it in a browser), as DXF (out/anchor_iso.dxf, for a CAD program)
# and as hlr-lines/1 JSON (out/anchor_iso.json).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
mkdir -p out
./build/app/hlr draw fixtures/parts/anchor.off --view iso -o out/anchor_iso.svg -o out/anchor_iso.dxf \
  -o out/anchor_iso.json
echo "Open out/anchor_iso.svg in a browser, or out/anchor_iso.dxf in a CAD program (LibreCAD)."
