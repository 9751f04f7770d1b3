#!/usr/bin/env bash
# The speed-versus-accuracy chart: every method hlr has, and Blender's Line Art, on the same
# meshes and views, in one run.
#
# usage (from anywhere; paths are relative to the repo root):
#   bench/chart/run.sh [MESH.off...]
#
# With no MESH arguments it takes every *.off of ../shared/scenes/ (when present), of
# fixtures/scenes/ and fixtures/parts/. For every mesh and view it runs
#   hlr check MESH --view V --raster 256,512,1024,2048,4096 --json ...   (exact + raster)
#   hlr check MESH --view V --kernels epick --json ...                   (exact + epick)
#   hlr check MESH --view V --kernels double --json ...                  (exact + double)
# each in its own process, so that a crash (a signal, or TIMEOUT) is charged to its method only,
# then Line Art through bench/draw/run.sh (KEEP, STROKES=1) and bench/draw/union_lengths.py.
# For every mesh, once, the shadow check (the chart's right panel; NO_SHADOWS=1 leaves it out):
#   hlr check MESH $SHADOW_LIGHTS --raster 64,256,1024,4096 --json ...   (exact + shadow maps)
# with SHADOW_LIGHTS three suns by default: oblique (1,2,-4), steep from the other side (-2,1,-1)
# and low, about 8 degrees above the horizon (1,0.3,-0.15). SHADOWS_ONLY=1 runs only those and
# redraws the line panel from LINES_CSV (an earlier run's CSV) instead.
# bench/chart/chart.py turns the reports into
#   bench/chart/results/<UTC date>.csv        one row per mesh, view and method
#   docs/images/speed_accuracy.svg and .png   the chart
# and prints the table docs/BENCHMARKS.md quotes.
#
# Accuracy of an hlr method: the fraction of the exact drawing's line length (all pieces, hidden
# ones under visible ones included) that the method classifies as the exact path does (hlr
# check's agreement); a run that fails, crashes or gives an invalid result counts as 0 for its
# case and is counted. Time: the method's drawing, without reading the mesh (hlr check's
# seconds). Line Art has no lines to match one by one: its accuracy is the fraction of hlr's
# exact drawn length (after ISO 128 precedence) that Line Art draws in the same class, within
# 1e-4 of the drawing's extent (union_lengths.py's *_hlr_only), and its time is its own timer.
#
# env: VIEWS (front,top,right,iso), SKIP, TIMEOUT (seconds per hlr run, default 600),
#      REPEAT (Line Art repeats, default 1), NO_PEER=1 (leave Line Art out), HLR, PYTHON,
#      KEEP=DIR (keep the reports), OUT (the CSV), NO_SHADOWS, SHADOWS_ONLY, SHADOW_LIGHTS, LINES_CSV,
#      LINES_LABEL.
# needs: a built hlr, /usr/bin/python3 with matplotlib (scripts/install-deps.sh), and for the
# peer point Blender (apt-get install -y blender).
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
TIMEOUT="${TIMEOUT:-600}" REPEAT="${REPEAT:-1}"
source "$here/../common.sh"
out="${OUT:-$here/results/$(date -u +%F).csv}"

bench_check
if [ $# -gt 0 ]; then
  meshes=("$@")
else
  shopt -s nullglob
  meshes=("$scenes"/*.off fixtures/scenes/*.off fixtures/parts/*.off)
  shopt -u nullglob
fi
bench_workdir
mkdir -p "$work/check"
bench_banner "chart: ${#meshes[@]} meshes"

IFS=',' read -r -a view_list <<<"$views"
read -r -a shadow_lights <<<"${SHADOW_LIGHTS:---sun 1,2,-4 --sun -2,1,-1 --sun 1,0.3,-0.15}"
shadows_only="${SHADOWS_ONLY:-0}"
if [ "$shadows_only" = 1 ] && [ -z "${LINES_CSV:-}" ]; then echo "SHADOWS_ONLY=1 needs LINES_CSV" >&2; exit 2; fi
peer_meshes=()
for mesh in "${meshes[@]}"; do
  name="$(basename "$mesh" .off)"
  bench_skip "$name" "$mesh" && continue
  # Fixture names may repeat a shared scene's (anchor): tag them by folder.
  case "$mesh" in fixtures/*) name="fixture_$name" ;; *) peer_meshes+=("$mesh") ;; esac
  if [ "${NO_SHADOWS:-0}" != 1 ]; then
    base="$work/check/${name}__lights__shadows"
    rc=0
    timeout "$timeout_s" "$hlr" check "$mesh" "${shadow_lights[@]}" --raster 64,256,1024,4096 --json "$base.json" \
      >"$base.log" 2>&1 || rc=$?
    echo "$rc" >"$base.rc"
    [ "$rc" = 0 ] || echo "hlr check shadows on $name: exit $rc (log: $base.log)" >&2
  fi
  if [ "$shadows_only" = 1 ]; then
    echo " $name"
    continue
  fi
  for view in "${view_list[@]}"; do
    for method in raster epick double; do
      case "$method" in
        raster) args=(--raster 256,512,1024,2048,4096) ;;
        *) args=(--kernels "$method") ;;
      esac
      base="$work/check/${name}__${view}__${method}"
      rc=0
      timeout "$timeout_s" "$hlr" check "$mesh" --view "$view" "${args[@]}" --json "$base.json" >"$base.log" 2>&1 || rc=$?
      echo "$rc" >"$base.rc"
      [ "$rc" = 0 ] || echo "hlr check $method on $name $view: exit $rc (log: $base.log)" >&2
    done
    printf '.'
  done
  echo " $name"
done

lengths=""
if [ "$shadows_only" != 1 ] && [ "${NO_PEER:-0}" != 1 ] && [ "$have_peer" = 1 ] && [ ${#peer_meshes[@]} -gt 0 ]; then
  KEEP="$work/draw" STROKES=1 OUT="$work/draw.csv" VIEWS="$views" REPEAT="$repeat" \
    bash "$here/../draw/run.sh" "${peer_meshes[@]}" >"$work/draw.log" 2>&1 || echo "Line Art run failed (log: $work/draw.log)" >&2
  "$py" "$here/../draw/union_lengths.py" "$work/draw" -o "$work/lengths.csv" >"$work/lengths.log" 2>&1 \
    && lengths="$work/lengths.csv" || echo "union_lengths failed (log: $work/lengths.log)" >&2
fi

"$py" "$here/chart.py" "$work/check" --out "$out" --images "$root/docs/images/speed_accuracy" \
  ${lengths:+--lineart-lengths "$lengths" --lineart-times "$work/draw.csv"} \
  ${LINES_CSV:+--lines-csv "$LINES_CSV" --lines-label "${LINES_LABEL:-$(basename "$LINES_CSV" .csv)}"} \
  --label "$(git rev-parse --short HEAD 2>/dev/null || echo '?'), $(date -u +%F)"
bench_done
