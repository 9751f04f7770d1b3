#!/usr/bin/env bash
# hlr shadows on the shared scene meshes: one sun, and a 7-step sun study.
#
# usage (from anywhere; paths are relative to the repo root):
#   bench/shadows/run.sh [MESH.off...]
#
# With no MESH arguments it takes every *.off in ../shared/scenes/ (exits 0 when that folder is
# absent). For every mesh it runs
#   hlr shadows MESH --sun 1,2,-4 -o X.json                                        (one sun)
#   hlr shadows MESH --sun-at 2026-06-21T09:00+10:00/15:00/PT1H --site -33.86,151.21 -o X.json
#                                                                                  (7 suns)
# and writes one CSV, bench/shadows/results/<UTC date>.csv, with columns
#   mesh, faces, lights, seconds, wall_seconds, us_per_face_light,
#   sources_s, light_views_s, sort_s, map_back_s
# seconds = stats.seconds of the JSON (reading and solving, not writing), wall_seconds the whole
# run (with the JSON written), us_per_face_light = seconds / (faces * lights) in microseconds;
# the stage columns are stats.stage_seconds. One run each: not rigorous timing.
#
# env: HLR (default build/app/hlr), PYTHON (default /usr/bin/python3), SKIP (comma list of mesh
# names without .off, default refined_elephant), OUT (the CSV), THREADS (hlr --threads, default 1).
set -euo pipefail
cd "$(dirname "$0")/../.."
hlr=${HLR:-build/app/hlr}
py=${PYTHON:-/usr/bin/python3}
skip=",${SKIP-refined_elephant},"
threads=${THREADS:-1}
out=${OUT:-bench/shadows/results/$(date -u +%Y-%m-%d).csv}
if [ $# -gt 0 ]; then meshes=("$@"); else
  [ -d ../shared/scenes ] || { echo "bench/shadows: no ../shared/scenes"; exit 0; }
  meshes=(../shared/scenes/*.off)
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
echo "mesh,faces,lights,seconds,wall_seconds,us_per_face_light,sources_s,light_views_s,sort_s,map_back_s" > "$out"
for mesh in "${meshes[@]}"; do
  name=$(basename "$mesh" .off)
  case "$skip" in *",$name,"*) echo "skip $name"; continue ;; esac
  for lights in 1 7; do
    if [ "$lights" = 1 ]; then args=(--sun 1,2,-4); else
      args=(--sun-at 2026-06-21T09:00+10:00/15:00/PT1H --site -33.86,151.21); fi
    start=$(date +%s.%N)
    "$hlr" shadows "$mesh" "${args[@]}" --threads "$threads" -o "$work/$name.json" > /dev/null
    end=$(date +%s.%N)
    "$py" - "$work/$name.json" "$name" "$lights" "$start" "$end" >> "$out" <<'PY'
import json, sys
doc = json.load(open(sys.argv[1]))
name, lights, start, end = sys.argv[2], int(sys.argv[3]), float(sys.argv[4]), float(sys.argv[5])
st = doc["stats"]; s = st["stage_seconds"]; faces = doc["input"]["faces"]
print(f"{name},{faces},{lights},{st['seconds']:.3f},{end - start:.3f},{1e6 * st['seconds'] / (faces * lights):.1f},"
      f"{s['sources']:.3f},{s['light_views']:.3f},{s['sort']:.3f},{s['map_back']:.3f}")
PY
    tail -1 "$out"
  done
done
echo "wrote $out"
