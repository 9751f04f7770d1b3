#!/usr/bin/env bash
# hlr draw on STEP parts beside OpenCASCADE's hidden-line removal, in one run.
#
# usage (paths relative to the repo root):  bench/cad/run.sh [PART.step...]
#
# With no arguments it makes the parts with OCC (build/cad/tests/cad_fixtures DIR --bench GRIDS):
# the test fixtures (plate, flange, bracket, assembly) and plates with a grid of N x N through
# holes, so that sizes vary. For every part and view it times, as whole processes (wall clock,
# `nice -n 0`, REPEAT runs, median; a run past TIMEOUT stops that case):
#   hlr   hlr draw PART --view V -o X.json           (STEP read, BRepMesh, exact drawing, JSON)
#   exact bench/cad/occ_step_hlr PART V --algo exact (STEP read, HLRBRep_Algo on the B-rep)
#   poly  bench/cad/occ_step_hlr PART V --algo poly  (STEP read, BRepMesh at hlr's deflection,
#                                                     HLRBRep_PolyAlgo)
# and writes bench/cad/results/<UTC date>.csv, one row per part and view:
#   part, faces (B-rep faces), triangles (hlr's input faces), view,
#   hlr_s, exact_s, poly_s       median wall seconds, or "timeout" / "failed"
#   hlr_vis, hlr_hid             stats.drawn_visible_length / drawn_hidden_length: what the
#                                drawing shows, after ISO 128 precedence (a hidden piece under a
#                                visible one dropped, coincident pieces once)
#   hlr_vis_all, hlr_hid_all     the sum of all pieces of the JSON's lines (before precedence: as
#                                OCC counts, every edge's own projection)
#   exact_vis, exact_hid         HLRBRep_Algo's sharp + outline lines (VCompound +
#                                OutLineVCompound; H... for hidden), OCC's projected curve lengths
#   exact_smooth_vis             its smooth (Rg1, tangent) visible lines: hlr leaves those out by
#                                default (--smooth-edges draws them)
#   poly_vis, poly_hid           the same classes of HLRBRep_PolyAlgo
#   vis_ratio, hid_ratio         hlr_vis_all / exact_vis, hlr_hid_all / exact_hid
# Lengths are 2D lengths in the view plane, model units.
#
# env: VIEWS (front,top,right,iso)  REPEAT (3)  TIMEOUT (300 s a run)  GRIDS ("10 20 40")
#      HLR (build/app/hlr)  FIXTURES (build/cad/tests/cad_fixtures)  OUT (CSV path)  KEEP=DIR
# needs: a Release build (build/), OCC's development packages (scripts/install-deps.sh), python3.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
cd "$root"
views="${VIEWS:-front,top,right,iso}"
repeat="${REPEAT:-3}"
limit="${TIMEOUT:-300}"
grids="${GRIDS:-10 20 40}"
hlr="${HLR:-$root/build/app/hlr}"
fixtures="${FIXTURES:-$root/build/cad/tests/cad_fixtures}"
out="${OUT:-$here/results/$(date -u +%F).csv}"
py=/usr/bin/python3
work="${KEEP:-$(mktemp -d)}"
mkdir -p "$work" "$(dirname "$out")"
for tool in "$hlr" "$fixtures"; do
  [ -x "$tool" ] || { echo "run.sh: $tool missing (build hlr with tests first)" >&2; exit 1; }
done

occ_build="$root/build/bench-cad-occ"
occ="$occ_build/occ_step_hlr"
if [ ! -x "$occ" ]; then
  { cmake -S "$here/occ_step_hlr" -B "$occ_build" -DCMAKE_BUILD_TYPE=Release && cmake --build "$occ_build" -j2; } \
    >"$work/occ_build.log" 2>&1 || { echo "run.sh: occ_step_hlr build failed ($work/occ_build.log)" >&2; exit 1; }
fi

if [ $# -gt 0 ]; then
  parts=("$@")
else
  # shellcheck disable=SC2086
  mkdir -p "$work/parts"
  "$fixtures" "$work/parts" --bench $grids
  parts=("$work/parts/plate.step" "$work/parts/flange.step" "$work/parts/bracket.step" "$work/parts/assembly.step")
  for n in $grids; do parts+=("$work/parts/grid_${n}x${n}.step"); done
fi

echo "hlr: $hlr ($(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo '?'))"
echo "OCC: $occ; views $views; repeat $repeat; timeout ${limit}s; $(nproc) cores; $(uname -r)"
runs="$work/runs.tsv"
: >"$runs"
# time_case TAG BASE CMD...: REPEAT runs of CMD; a line "TAG BASE status seconds..." in $runs.
time_case() {
  local tag="$1" base="$2"
  shift 2
  local times="" status=ok
  for _ in $(seq "$repeat"); do
    local t0 t1 rc=0
    t0=$(date +%s.%N)
    timeout "$limit" nice -n 0 "$@" >"$base.log" 2>&1 || rc=$?
    t1=$(date +%s.%N)
    if [ "$rc" -eq 124 ]; then status=timeout; break; fi
    if [ "$rc" -ne 0 ]; then status=failed; break; fi
    times="$times $(echo "$t1 - $t0" | bc -l)"
  done
  echo "$tag	$base	$status	$times" >>"$runs"
  echo "  $tag: $status$times"
}

for part in "${parts[@]}"; do
  name="$(basename "${part%.*}")"
  for view in ${views//,/ }; do
    echo "$name $view"
    base="$work/${name}_$view"
    time_case "$name,$view,hlr" "$base.hlr" "$hlr" draw "$part" --view "$view" -o "$base.hlr.json"
    time_case "$name,$view,exact" "$base.exact" "$occ" "$part" "$view" --algo exact --json "$base.exact.json"
    time_case "$name,$view,poly" "$base.poly" "$occ" "$part" "$view" --algo poly --json "$base.poly.json"
  done
done

"$py" - "$runs" "$out" <<'EOF'
import csv, json, math, statistics, sys
runs, out = sys.argv[1], sys.argv[2]
cases = {}
for line in open(runs):
    tag, base, status, *times = line.rstrip("\n").split("\t")
    part, view, tool = tag.split(",")
    secs = [float(t) for t in " ".join(times).split()]
    cases.setdefault((part, view), {})[tool] = (base, status, secs)

def load(path):
    try:
        return json.load(open(path))
    except (OSError, ValueError):
        return None

def fmt(x, digits=4):
    return "" if x is None else (f"{x:.{digits}f}" if isinstance(x, float) else str(x))

rows = []
for (part, view), tools in cases.items():
    row = {"part": part, "view": view}
    for tool in ("hlr", "exact", "poly"):
        base, status, secs = tools[tool]
        row[f"{tool}_s"] = fmt(statistics.median(secs), 3) if status == "ok" and secs else status
    hlr = load(tools["hlr"][0] + ".json")
    exact = load(tools["exact"][0] + ".json")
    poly = load(tools["poly"][0] + ".json")
    if hlr:
        row["triangles"] = hlr["input"]["faces"]
        row["hlr_vis"] = fmt(hlr["stats"]["drawn_visible_length"])
        row["hlr_hid"] = fmt(hlr["stats"]["drawn_hidden_length"])
        length = lambda l: math.hypot(l["b"][0] - l["a"][0], l["b"][1] - l["a"][1])
        vis_all = sum(length(l) for l in hlr["lines"] if l["visible"])
        hid_all = sum(length(l) for l in hlr["lines"] if not l["visible"])
        row["hlr_vis_all"], row["hlr_hid_all"] = fmt(vis_all), fmt(hid_all)
    for tool, doc in (("exact", exact), ("poly", poly)):
        if doc:
            row["faces"] = doc["faces"]
            row[f"{tool}_vis"] = fmt(doc["visible"]["length"])
            row[f"{tool}_hid"] = fmt(doc["hidden"]["length"])
            if tool == "exact":
                row["exact_smooth_vis"] = fmt(doc["visible"]["smooth"])
    if hlr and exact:
        ev, eh = exact["visible"]["length"], exact["hidden"]["length"]
        row["vis_ratio"] = fmt(vis_all / ev) if ev > 0 else "n/a"
        row["hid_ratio"] = fmt(hid_all / eh) if eh > 0 else "n/a"
    rows.append(row)
columns = ["part", "faces", "triangles", "view", "hlr_s", "exact_s", "poly_s", "hlr_vis", "hlr_hid", "hlr_vis_all",
           "hlr_hid_all", "exact_vis", "exact_hid", "exact_smooth_vis", "poly_vis", "poly_hid", "vis_ratio", "hid_ratio"]
with open(out, "w", newline="") as f:
    w = csv.DictWriter(f, fieldnames=columns, restval="")
    w.writeheader()
    w.writerows(rows)
print(f"wrote {out}")
print("| part | faces | triangles | view | hlr s | HLRBRep_Algo s | HLRBRep_PolyAlgo s | vis hlr/Algo | hid hlr/Algo |")
print("|---|---:|---:|---|---:|---:|---:|---:|---:|")
for r in rows:
    print(f"| {r['part']} | {r.get('faces', '')} | {r.get('triangles', '')} | {r['view']} | {r['hlr_s']} | {r['exact_s']} | "
          f"{r['poly_s']} | {r.get('vis_ratio', '')} | {r.get('hid_ratio', '')} |")
EOF
[ -n "${KEEP:-}" ] || rm -rf "$work"
