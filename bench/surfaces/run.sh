#!/usr/bin/env bash
# hlr surfaces beside Blender's Line Art, on the shared scene meshes, in one run.
#
# usage (from anywhere; paths are relative to the repo root):
#   bench/surfaces/run.sh [MESH.off...]
#
# With no MESH arguments it takes every *.off in ../shared/scenes/ (relative to the repo root);
# if that folder is absent it says so and exits 0. For every mesh and view it runs
#   hlr surfaces MESH --view V --kernel K -o X.json      for K in exact, epick, double
# and the peer script ../shared/peers/blender_lineart/run.sh (Blender Line Art) on the same
# mesh and views, then writes one CSV:
#   bench/surfaces/results/<UTC date>.csv
# columns: mesh, view, faces, sources, hlr_exact_s, hlr_epick_s, hlr_double_s, lineart_s,
#          ratio_exact_lineart
#   hlr_*_s      stats.seconds of hlr's JSON (total: read + sources + sort; minimum over
#                HLR_REPEAT runs), or "failed" when
#                hlr exits non-zero (expected often for epick/double on real meshes) or times out
#   faces        stats.faces (input faces), sources = stats.sources (polygons after back-face
#                removal and consolidation), both from the exact kernel (else the first kernel
#                that succeeded)
#   lineart_s    the peer's lineart_seconds (Line Art's own timer, minimum of REPEAT runs), or
#                "failed"
#   ratio_exact_lineart = hlr_exact_s / lineart_s (> 1: hlr is slower), or "n/a"
# It also prints hlr's stage_seconds (read / sources / sort) for the exact kernel, and keeps
# logs of failures in the work folder.
#
# env:
#   VIEWS    comma list of views                 (default front,top,right,iso)
#   KERNELS  comma list of hlr kernels           (default exact,epick,double)
#   SKIP     comma list of mesh names to skip, without .off (default none), e.g. SKIP=refined_elephant
#   REPEAT   peer repeats (minimum is taken)     (default 5; REPEAT=1 when time is short)
#   HLR_REPEAT  runs of each hlr command; the one with the least stats.seconds is reported
#            (default 1)
#   THREADS  peer threads                        (default 1; hlr is single-threaded)
#   TIMEOUT  seconds allowed per hlr run, 0 = no limit (default 0); a timeout counts as "failed"
#   HLR      hlr binary                          (default build/app/hlr)
#   PYTHON   python for JSON/CSV work            (default /usr/bin/python3)
#   OUT      CSV to write                        (default bench/surfaces/results/<UTC date>.csv)
#   KEEP=DIR keep every hlr JSON/log and the peer's SVG/JSON/logs in DIR (default: a temp dir,
#            removed at the end unless something failed)
# needs: a built hlr (build/app/hlr) and Blender (apt-get install -y blender).
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
cd "$root"

views="${VIEWS:-front,top,right,iso}"
kernels="${KERNELS:-exact,epick,double}"
skip=",${SKIP:-},"
repeat="${REPEAT:-5}"
hlr_repeat="${HLR_REPEAT:-1}"
threads="${THREADS:-1}"
timeout_s="${TIMEOUT:-0}"
hlr="${HLR:-$root/build/app/hlr}"
py="${PYTHON:-/usr/bin/python3}"
peer="$root/../shared/peers/blender_lineart/run.sh"
scenes="$root/../shared/scenes"
out="${OUT:-$here/results/$(date -u +%F).csv}"

[ -x "$hlr" ] || { echo "no hlr binary at $hlr (build the project first)" >&2; exit 1; }
[ -x "$py" ] || { echo "no python at $py" >&2; exit 1; }
have_peer=1
if [ ! -f "$peer" ]; then echo "peer script $peer absent: lineart_s will be \"failed\"" >&2; have_peer=0; fi
if [ "$have_peer" = 1 ] && ! command -v blender >/dev/null; then
  echo "blender not installed (apt-get install -y blender): lineart_s will be \"failed\"" >&2; have_peer=0
fi

meshes=()
if [ $# -gt 0 ]; then
  meshes=("$@")
else
  if [ ! -d "$scenes" ]; then echo "no scenes folder $scenes: nothing to do" >&2; exit 0; fi
  shopt -s nullglob
  meshes=("$scenes"/*.off)
  shopt -u nullglob
  [ ${#meshes[@]} -gt 0 ] || { echo "no .off meshes in $scenes: nothing to do" >&2; exit 0; }
fi

if [ -n "${KEEP:-}" ]; then work="$KEEP"; mkdir -p "$work"; keep=1; else work="$(mktemp -d)"; keep=0; fi
mkdir -p "$(dirname "$out")"
rows="$work/rows.tsv"          # mesh view kernel status json
: >"$rows"
any_fail=0

echo "hlr: $hlr ($(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo '?'))"
echo "peer: $([ "$have_peer" = 1 ] && blender -b --version 2>/dev/null | head -1 || echo absent), REPEAT=$repeat THREADS=$threads"
echo "HLR_REPEAT=$hlr_repeat TIMEOUT=$timeout_s VIEWS=$views KERNELS=$kernels SKIP=${SKIP:-}"
echo "work: $work"

for mesh in "${meshes[@]}"; do
  name="$(basename "${mesh%.*}")"
  if [ ! -f "$mesh" ]; then echo "skip $name: $mesh absent" >&2; continue; fi
  if [[ "$skip" == *",$name,"* ]]; then echo "skip $name (SKIP)"; continue; fi
  for view in ${views//,/ }; do
    for k in ${kernels//,/ }; do
      base="$work/hlr_${name}_${view}_${k}"
      cmd=("$hlr" surfaces "$mesh" --view "$view" --kernel "$k" -o "$base.json")
      if [ "$timeout_s" != 0 ]; then cmd=(timeout "$timeout_s" "${cmd[@]}"); fi
      : >"$base.stats"; status=ok
      for ((r = 1; r <= hlr_repeat; r++)); do
        rm -f "$base.json"
        if "${cmd[@]}" >"$base.log" 2>&1 && [ -s "$base.json" ]; then
          # keep only the stats, one JSON line per repeat (the polygons can be large)
          "$py" -c 'import json, sys; print(json.dumps(json.load(open(sys.argv[1]))["stats"]))' \
            "$base.json" >>"$base.stats"
          rm -f "$base.json"
        else
          rc=$?; status=failed
          echo "hlr $k failed on $name $view (exit $rc; log: $base.log)" >&2
          if [ "$k" = exact ]; then any_fail=1; fi
          break
        fi
      done
      printf '%s\t%s\t%s\t%s\t%s\n' "$name" "$view" "$k" "$status" "$base.stats" >>"$rows"
    done
  done
  if [ "$have_peer" = 1 ]; then
    mkdir -p "$work/peer"
    THREADS="$threads" REPEAT="$repeat" KEEP="$work/peer" bash "$peer" "$work/peer_${name}.csv" "$views" "$mesh" \
      || { echo "peer run failed on $name" >&2; any_fail=1; }
  fi
done

"$py" - "$rows" "$work" "$out" "$views" <<'EOF'
import csv, glob, json, os, sys
rows_tsv, work, out, views = sys.argv[1:5]
hlr = {}     # (mesh, view) -> {kernel: stats or None}
order = []
for line in open(rows_tsv):
    mesh, view, k, status, path = line.rstrip("\n").split("\t")
    key = (mesh, view)
    if key not in hlr:
        hlr[key] = {}
        order.append(key)
    runs = [json.loads(l) for l in open(path) if l.strip()] if status == "ok" else []
    hlr[key][k] = min(runs, key=lambda st: st["seconds"]) if runs else None
peer = {}
for p in glob.glob(os.path.join(work, "peer_*.csv")):
    for r in csv.DictReader(open(p)):
        peer[(r["mesh"], r["view"])] = r

def sec(s):
    return "%.6f" % s["seconds"] if s else "failed"

cols = ["mesh", "view", "faces", "sources", "hlr_exact_s", "hlr_epick_s", "hlr_double_s",
        "lineart_s", "ratio_exact_lineart"]
with open(out, "w", newline="") as f:
    w = csv.writer(f)
    w.writerow(cols)
    print("\n%-24s %-5s %7s %7s %10s %10s %10s %10s %8s | exact stages: read / sources / sort"
          % tuple(c[:10] for c in cols))
    for key in order:
        ks = hlr[key]
        ref = ks.get("exact") or next((s for s in ks.values() if s), None)
        pr = peer.get(key)
        faces = ref["faces"] if ref else (pr["faces"] if pr else "")
        sources = ref["sources"] if ref else ""
        la = float(pr["lineart_seconds"]) if pr else None
        ex = ks.get("exact")
        ratio = "%.1f" % (ex["seconds"] / la) if (ex and la) else "n/a"
        row = [key[0], key[1], faces, sources, sec(ks.get("exact")), sec(ks.get("epick")),
               sec(ks.get("double")), "%.6f" % la if la is not None else "failed", ratio]
        w.writerow(row)
        st = ""
        if ex:
            g = ex["stage_seconds"]
            st = "%.3f / %.3f / %.3f" % (g["read"], g["sources"], g["sort"])
        print("%-24s %-5s %7s %7s %10s %10s %10s %10s %8s | %s" % tuple(map(str, row + [st])))
print("\nwrote", out)
EOF

if [ "$keep" = 0 ] && [ "$any_fail" = 0 ]; then rm -rf "$work"; else echo "kept $work"; fi
