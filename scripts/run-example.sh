#!/usr/bin/env bash
# Quick start (1): install, build, and run the main job on a bundled sample.
# Clips fixtures/clip/subject.json by fixtures/clip/clip.json and writes out/clip-result.json.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
mkdir -p out
./build/app/hlr clip fixtures/clip/subject.json fixtures/clip/clip.json -o out/clip-result.json
