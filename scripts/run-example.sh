#!/usr/bin/env bash
# Quick start (1): install, build, and run the main jobs on bundled samples:
#   - the hidden-surface solution of fixtures/scenes/l_bracket.off in the iso view, written as a
#     picture (out/l_bracket_iso.svg) and as hlr-surfaces/1 JSON (out/l_bracket_iso.json);
#   - the clipper on fixtures/clip/subject.json and clip.json (out/clip-result.json).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
mkdir -p out
./build/app/hlr surfaces fixtures/scenes/l_bracket.off --view iso -o out/l_bracket_iso.svg -o out/l_bracket_iso.json
./build/app/hlr clip fixtures/clip/subject.json fixtures/clip/clip.json -o out/clip-result.json
echo "Open out/l_bracket_iso.svg in a browser to see the result."
