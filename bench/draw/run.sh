#!/usr/bin/env bash
# hlr draw beside Blender's Line Art, on the shared scene meshes, in one run.
#
# usage (from anywhere; paths are relative to the repo root):
#   bench/draw/run.sh [MESH.off...]
#
# With no MESH arguments it takes every *.off in ../shared/scenes/ (relative to the repo root);
# if that folder is absent it says so and exits 0. For every mesh and view it runs
#   hlr draw MESH --view V --kernel exact -o X.json
# and the peer script ../shared/peers/blender_lineart/run.sh (Blender Line Art) on the same
# mesh and views, then writes one CSV:
#   bench/draw/results/<UTC date>.csv
# columns: mesh, view, faces, feature_lines, hlr_s, hlr_lines_s, hlr_intersections_s,
#          hlr_precedence_s, lineart_s, ratio, hlr_vis_len, hlr_hid_len, hlr_hid_len_all,
#          lineart_vis_len, lineart_hid_len, vis_len_ratio, hid_len_ratio
#   faces            stats/input faces of hlr's JSON (else the peer's)
#   feature_lines    stats.lines: feature lines hlr found (silhouette, crease, boundary, group,
#                    intersection), before splitting into visible and hidden pieces
#   hlr_s            stats.seconds (total: read + sources + sort + intersections + lines +
#                    precedence + write, the output stage up to the JSON's stats; older hlr builds
#                    have no write stage), minimum over HLR_REPEAT runs, or "failed"
#                    (non-zero exit or timeout)
#   hlr_lines_s      stats.stage_seconds.lines of that run: classifying the feature lines into
#                    visible and hidden pieces only. (Before the stage split, at 74750b5, "lines"
#                    also held the penetration search and precedence: compare older CSVs with
#                    the sum of the three columns.)
#   hlr_intersections_s  stats.stage_seconds.intersections: the penetration search
#                    (intersection lines between faces)
#   hlr_precedence_s stats.stage_seconds.precedence: ISO 128 precedence (hidden under visible
#                    removed, coincident duplicates once)
#                    These three are "n/a" when the hlr binary's JSON lacks that stage.
#   lineart_s        the peer's lineart_seconds (Line Art's own timer, minimum of REPEAT runs),
#                    or "failed"
#   ratio            hlr_s / lineart_s (> 1: hlr is slower), or "n/a"
#   hlr_warm_s       the same work timed as the peer is: the least stats.seconds of WARM_RUNS runs
#                    in one process (build/bench/draw_warm; its header says why), or "n/a"
#   warm_ratio       hlr_warm_s / lineart_s
#   hlr_vis_len, hlr_hid_len
#                    stats.drawn_visible_length / drawn_hidden_length: 2D length of what the
#                    drawing shows after ISO 128 precedence (hidden under visible removed,
#                    coincident duplicates once); model units, orthonormal view frame
#   hlr_hid_len_all  2D length of ALL hidden pieces of the JSON "lines", before precedence
#   lineart_vis_len, lineart_hid_len
#                    the peer's vis_len / hid_len: 2D length of Line Art's visible (occlusion
#                    level 0) and hidden (levels 1-128) strokes, in the camera's right/up frame,
#                    world units (the same frame and scale as hlr's)
#   vis_len_ratio    hlr_vis_len / lineart_vis_len; hid_len_ratio = hlr_hid_len / lineart_hid_len
#                    ("n/a" when a side is missing or the peer's length is 0)
# It also prints hlr's stage split (read / sources / sort / intersections / lines / precedence /
# write) per case and summed.
#
# env:
#   VIEWS    comma list of views                 (default front,top,right,iso)
#   SKIP     comma list of mesh names to skip, without .off (default none), e.g. SKIP=refined_elephant
#   REPEAT   peer repeats (minimum is taken)     (default 5; REPEAT=1 when time is short)
#   HLR_REPEAT  runs of each hlr command; the one with the least stats.seconds is reported
#            (default 1)
#   THREADS  peer threads                        (default 1)
#   HLR_THREADS  hlr --threads N                  (default: hlr's default, every core)
#   TIMEOUT  seconds allowed per hlr run, 0 = no limit (default 0); a timeout counts as "failed"
#   HLR      hlr binary                          (default build/app/hlr)
#   PYTHON   python for JSON/CSV work            (default /usr/bin/python3)
#   OUT      CSV to write                        (default bench/draw/results/<UTC date>.csv)
#   WARM     the draw_warm binary (default build/bench/draw_warm; WARM=0: no warm runs)
#   WARM_RUNS  runs per case in that one process (default 5, as the peer's REPEAT)
#   KEEP=DIR keep hlr's JSON (the last run's), stats and logs, and the peer's SVG/JSON/logs in
#            DIR (default: a temp dir, removed at the end unless something failed)
#   STROKES=1  with KEEP: after the timed runs, run the peer's lineart_measure.py once more per
#            mesh and view (--repeat 1, untimed, not in the CSV) with --strokes, into
#            DIR/peer/<mesh>_<view>.strokes.json: every stroke at full precision, for
#            bench/draw/union_lengths.py (which else reads the SVG, rounded to 0.001 px)
# Lengths of both tools under one rule (union of coincident segments, hidden under visible
# removed) and what only one tool draws: bench/draw/union_lengths.py DIR on a KEEP folder.
# The option handling, the timed hlr runs and the peer run are shared with
# bench/surfaces/run.sh in bench/common.sh and bench/common.py.
# needs: a built hlr (build/app/hlr) and Blender (apt-get install -y blender).
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
source "$here/../common.sh"    # options, mesh list, work folder, hlr and peer runs; cd to the root
out="${OUT:-$here/results/$(date -u +%F).csv}"
if [ -n "${KEEP:-}" ]; then KEEP_HLR_JSON=1; fi

bench_check
bench_meshes "$@"
bench_workdir
mkdir -p "$(dirname "$out")"
bench_banner "(hlr draw, exact kernel)"
warm="${WARM:-$root/build/bench/draw_warm}"
if [ "$warm" != 0 ] && [ ! -x "$warm" ]; then echo "no draw_warm at $warm: hlr_warm_s will be n/a" >&2; warm=0; fi

for mesh in "${meshes[@]}"; do
  name="$(basename "${mesh%.*}")"
  if bench_skip "$name" "$mesh"; then continue; fi
  for view in ${views//,/ }; do
    bench_hlr "$name" "$view" exact "$work/hlr_${name}_${view}" \
      draw "$mesh" --view "$view" --kernel exact || any_fail=1
    if [ "$warm" != 0 ]; then
      "$warm" "$mesh" "$view" "${WARM_RUNS:-5}" "${hlr_threads:-0}" >"$work/warm_${name}_${view}.json" \
        || { echo "draw_warm failed on $name $view" >&2; rm -f "$work/warm_${name}_${view}.json"; any_fail=1; }
    fi
  done
  bench_peer "$mesh" "$name"
  if [ "${STROKES:-0}" = 1 ] && [ "$keep" = 1 ] && [ "$have_peer" = 1 ]; then
    for view in ${views//,/ }; do
      blender -b -noaudio -t "$threads" -P "$(dirname "$peer")/lineart_measure.py" -- --off "$mesh" \
        --view "$view" --threads "$threads" --repeat 1 --strokes "$work/peer/${name}_${view}.strokes.json" \
        >"$work/peer/${name}_${view}.strokes.log" 2>&1 \
        || echo "peer strokes failed on $name $view (log: $work/peer/${name}_${view}.strokes.log)" >&2
    done
  fi
done

BENCH_DIR="$bench_dir" "$py" - "$rows" "$work" "$out" <<'EOF'
import csv, json, math, os, sys
sys.path.insert(0, os.environ["BENCH_DIR"])
from common import load_hlr, load_peer, sec
rows_tsv, work, out = sys.argv[1:4]
order, hlr = load_hlr(rows_tsv)    # (mesh, view) -> {"exact": best stats or None}
peer = load_peer(work)

def ratio(a, b, fmt):
    return fmt % (a / b) if (a is not None and b) else "n/a"

def num(x):
    return "%.6f" % x if x is not None else "failed"

cols = ["mesh", "view", "faces", "feature_lines", "hlr_s", "hlr_lines_s", "hlr_intersections_s",
        "hlr_precedence_s", "lineart_s", "ratio", "hlr_vis_len", "hlr_hid_len", "hlr_hid_len_all",
        "lineart_vis_len", "lineart_hid_len", "vis_len_ratio", "hid_len_ratio", "hlr_warm_s", "warm_ratio"]

def warm_seconds(key):
    try:
        with open(os.path.join(work, "warm_%s_%s.json" % key)) as f:
            return json.load(f)["seconds"]
    except (OSError, ValueError, KeyError):
        return None
stages = ["read", "sources", "sort", "intersections", "lines", "precedence", "write"]

def stage(ex, s):
    if not ex:
        return "failed"
    g = ex.get("stage_seconds", {})
    return "%.6f" % g[s] if s in g else "n/a"

fmt = "%-20s %-5s %6s %6s %9s %9s %9s %9s %9s %6s %10s %10s %10s %10s %10s %6s %6s %9s %6s"
timed = (4, 5, 6, 7, 8, 17)   # columns printed as seconds, cut to 9 characters
total = dict.fromkeys(stages, 0.0)
with open(out, "w", newline="") as f:
    w = csv.writer(f)
    w.writerow(cols)
    print("\n" + fmt % tuple(c[:10] for c in cols)
          + " | stages: read/sources/sort/intersections/lines/precedence/write")
    for key in order:
        ex = hlr[key].get("exact")
        pr = peer.get(key)
        la = float(pr["lineart_seconds"]) if pr else None
        lav = float(pr["vis_len"]) if pr else None
        lah = float(pr["hid_len"]) if pr else None
        hv = ex["drawn_visible_length"] if ex else None
        hh = ex["drawn_hidden_length"] if ex else None
        row = [key[0], key[1], ex["faces"] if ex else (pr["faces"] if pr else ""),
               ex["lines"] if ex else "", sec(ex),
               stage(ex, "lines"), stage(ex, "intersections"), stage(ex, "precedence"),
               num(la), ratio(ex["seconds"] if ex else None, la, "%.2f"),
               num(hv), num(hh), num(ex["bench_hidden_length_all"] if ex else None),
               num(lav), num(lah), ratio(hv, lav, "%.4f"), ratio(hh, lah, "%.4f")]
        hw = warm_seconds(key)
        row += ["%.6f" % hw if hw is not None else "n/a", ratio(hw, la, "%.2f")]
        w.writerow(row)
        st = ""
        if ex:
            g = ex["stage_seconds"]
            for s in stages:
                total[s] += g.get(s, 0.0)
            st = " / ".join("%.3f" % g[s] if s in g else "n/a" for s in stages)
        print(fmt % tuple(
            (c[:9] if i in timed else c) if isinstance(c, str) else str(c)
            for i, c in enumerate(row)) + " | " + st)
for col in ("ratio", "warm_ratio"):
    with open(out) as f:
        rs = [float(r[col]) for r in csv.DictReader(f) if r[col] not in ("n/a", "")]
    if rs:
        print("%s: geometric mean %.2f, median %.2f, max %.2f over %d cases" % (
            col, math.exp(sum(map(math.log, rs)) / len(rs)), sorted(rs)[len(rs) // 2], max(rs), len(rs)))
s = sum(total.values())
if s:
    print("\nhlr stage split, summed over all cases: " +
          ", ".join("%s %.1f%%" % (k, 100 * v / s) for k, v in total.items()) +
          " (of %.2f s)" % s)
print("\nwrote", out)
EOF

bench_done
