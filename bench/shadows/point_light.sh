#!/usr/bin/env bash
# hlr shadows with one point light beside one sun, on the shared scene meshes.
#
# usage (from anywhere; paths are relative to the repo root):
#   bench/shadows/point_light.sh [MESH.off...]     (default: part joint anchor rotor pinion
#                                                   couplingdown fandisk from ../shared/scenes)
# For every mesh it runs
#   hlr shadows MESH --sun 1,2,-4 --threads 1 -o X.json
#   hlr shadows MESH --point-light P --threads 1 -o X.json
# with P = c - 2 s (1,2,-4)/|(1,2,-4)| on a 1/16 grid (c the centre of the mesh's bounding box,
# s its largest side): a light from about where the sun comes from, two sizes away. Columns as in
# run.sh (mesh, light, position, seconds, stage seconds); one run each: not rigorous timing.
#
# env: HLR (default build/app/hlr), PYTHON (default /usr/bin/python3), OUT (the CSV).
set -euo pipefail
cd "$(dirname "$0")/../.."
hlr=${HLR:-build/app/hlr}
py=${PYTHON:-/usr/bin/python3}
out=${OUT:-bench/shadows/results/$(date -u +%Y-%m-%d)-point.csv}
if [ $# -gt 0 ]; then meshes=("$@"); else
  [ -d ../shared/scenes ] || { echo "bench/shadows: no ../shared/scenes"; exit 0; }
  meshes=()
  for n in part joint anchor rotor pinion couplingdown fandisk; do meshes+=("../shared/scenes/$n.off"); done
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
echo "mesh,faces,light,seconds,sources_s,light_views_s,sort_s,map_back_s" > "$out"
for mesh in "${meshes[@]}"; do
  name=$(basename "$mesh" .off)
  position=$("$py" - "$mesh" <<'PY'
import math, sys
lines = [l.split('#')[0].split() for l in open(sys.argv[1])]
lines = [l for l in lines if l]
if lines[0][0] == 'OFF' and len(lines[0]) == 1: lines = lines[1:]
elif lines[0][0].startswith('OFF'): lines[0] = lines[0][1:]
nv = int(lines[0][0])
pts = [[float(v) for v in l[:3]] for l in lines[1:1 + nv]]
lo = [min(p[k] for p in pts) for k in range(3)]; hi = [max(p[k] for p in pts) for k in range(3)]
s = max(hi[k] - lo[k] for k in range(3)); d = [1, 2, -4]; n = math.sqrt(21)
print(','.join(str(round(((lo[k] + hi[k]) / 2 - 2 * s * d[k] / n) * 16) / 16) for k in range(3)))
PY
)
  for light in "--sun 1,2,-4" "--point-light $position"; do
    # shellcheck disable=SC2086
    "$hlr" shadows "$mesh" $light --threads 1 -o "$work/$name.json" > /dev/null
    "$py" - "$work/$name.json" "$name" "$light" >> "$out" <<'PY'
import json, sys
doc = json.load(open(sys.argv[1]))
st = doc["stats"]; s = st["stage_seconds"]
print(f"{sys.argv[2]},{doc['input']['faces']},{sys.argv[3]},{st['seconds']:.3f},"
      f"{s['sources']:.3f},{s['light_views']:.3f},{s['sort']:.3f},{s['map_back']:.3f}")
PY
    tail -1 "$out"
  done
done
echo "wrote $out"
