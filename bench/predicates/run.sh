#!/usr/bin/env bash
# How the exact kernel decides its predicates (issue 12): for every mesh and view, runs
#   HLR_PREDICATE_STATS=1 hlr draw MESH --view V --threads 1 -o X.json
# and reads the counts hlr prints on exit (app/src/main.cpp): per predicate family (orientation,
# comparison, sign), how many decisions took no arithmetic (the same point twice), intervals
# (the approximations Epeck keeps), exact arithmetic on doubles (points whose coordinates are
# doubles: Epick's filter and Mpzf), or exact rational arithmetic (GMP). Decisions that callers take from
# support-line ids and mesh incidences (rule 3) never reach the kernel and are not counted.
#
# usage (from anywhere; paths are relative to the repo root):
#   bench/predicates/run.sh [MESH.off...]      (default: every ../shared/scenes/*.off)
# writes bench/predicates/results/<UTC date>.csv with columns
#   mesh, view, seconds, then <family>_identity, _interval, _doubles, _exact per family,
# and prints a table of the exact share per family.
# env: VIEWS (default front,top,right,iso), HLR (default build/app/hlr), OUT (CSV to write)
set -euo pipefail
cd "$(dirname "$0")/../.."
hlr="${HLR:-build/app/hlr}"
views="${VIEWS:-front,top,right,iso}"
out="${OUT:-bench/predicates/results/$(date -u +%F).csv}"
[ -x "$hlr" ] || { echo "no hlr binary at $hlr (build the project first)" >&2; exit 1; }
meshes=("$@")
if [ ${#meshes[@]} -eq 0 ]; then
  shopt -s nullglob
  meshes=(../shared/scenes/*.off)
  [ ${#meshes[@]} -gt 0 ] || { echo "no meshes in ../shared/scenes: nothing to measure"; exit 0; }
fi
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
mkdir -p "$(dirname "$out")"
echo "mesh,view,seconds,orientation_identity,orientation_interval,orientation_doubles,orientation_exact,comparison_identity,comparison_interval,comparison_doubles,comparison_exact,sign_identity,sign_interval,sign_doubles,sign_exact" >"$out"
for mesh in "${meshes[@]}"; do
  name="$(basename "${mesh%.*}")"
  for view in ${views//,/ }; do
    HLR_PREDICATE_STATS=1 "$hlr" draw "$mesh" --view "$view" --threads 1 -o "$work/x.json" >/dev/null 2>"$work/err" ||
      { echo "$name $view: hlr failed ($(tail -1 "$work/err"))" >&2; continue; }
    /usr/bin/python3 - "$work/err" "$work/x.json" "$name" "$view" >>"$out" <<'PY'
import json, re, sys
counts = {}
for line in open(sys.argv[1]):
    m = re.match(r"hlr: predicates (\w+): identity (\d+), interval (\d+), doubles (\d+), exact (\d+)", line)
    if m: counts[m.group(1)] = m.groups()[1:]
seconds = json.load(open(sys.argv[2]))["stats"]["seconds"]
row = [sys.argv[3], sys.argv[4], "%.6f" % seconds]
for family in ("orientation", "comparison", "sign"):
    row += counts.get(family, ("", "", "", ""))
print(",".join(row))
PY
  done
done
/usr/bin/python3 - "$out" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
print("| mesh | view | orientations | doubles | exact | comparisons | exact | signs | exact |")
print("|---|---|---:|---:|---:|---:|---:|---:|---:|")
for r in rows:
    cells = []
    for f in ("orientation", "comparison", "sign"):
        n = sum(int(r[f + "_" + k]) for k in ("identity", "interval", "doubles", "exact"))
        share = lambda k: "%.2f%%" % (100.0 * int(r[f + "_" + k]) / n if n else 0)
        cells += [str(n)] + ([share("doubles")] if f == "orientation" else []) + [share("exact")]
    print("| %s | %s | %s |" % (r["mesh"], r["view"], " | ".join(cells)))
PY
echo "wrote $out"
