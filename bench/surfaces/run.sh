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
#   hlr_*_s      stats.seconds of hlr's JSON (total: read + sources + sort + write, the JSON
#                made; builds before 2026-12-07 leave out write; minimum over
#                HLR_REPEAT runs), "not run" for a kernel KERNELS leaves out, or "failed" when
#                hlr exits non-zero (expected often for epick/double on real meshes) or times out
#   faces        stats.faces (input faces), sources = stats.sources (polygons after back-face
#                removal and consolidation), both from the exact kernel (else the first kernel
#                that succeeded)
#   lineart_s    the peer's lineart_seconds (Line Art's own timer, minimum of REPEAT runs), or
#                "failed"
#   ratio_exact_lineart = hlr_exact_s / lineart_s (> 1: hlr is slower), or "n/a"
# It also prints hlr's stage_seconds (read / sources / sort / write) for the exact kernel, and keeps
# logs of failures in the work folder.
#
# env:
#   VIEWS    comma list of views                 (default front,top,right,iso)
#   KERNELS  comma list of hlr kernels           (default exact,epick,double)
#   SKIP     comma list of mesh names to skip, without .off (default none), e.g. SKIP=refined_elephant
#   REPEAT   peer repeats (minimum is taken)     (default 5; REPEAT=1 when time is short)
#   HLR_REPEAT  runs of each hlr command; the one with the least stats.seconds is reported
#            (default 1)
#   THREADS  peer threads                        (default 1; HLR_THREADS sets hlr's, bench/common.sh)
#   TIMEOUT  seconds allowed per hlr run, 0 = no limit (default 0); a timeout counts as "failed"
#   HLR      hlr binary                          (default build/app/hlr)
#   PYTHON   python for JSON/CSV work            (default /usr/bin/python3)
#   OUT      CSV to write                        (default bench/surfaces/results/<UTC date>.csv)
#   KEEP=DIR keep every hlr stats/log and the peer's SVG/JSON/logs in DIR (default: a temp dir,
#            removed at the end unless something failed); hlr's JSON stays too with
#            KEEP_HLR_JSON=1 (the last run's)
# The option handling, the timed hlr runs and the peer run are shared with bench/draw/run.sh in
# bench/common.sh and bench/common.py.
# needs: a built hlr (build/app/hlr) and Blender (apt-get install -y blender).
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
source "$here/../common.sh"    # options, mesh list, work folder, hlr and peer runs; cd to the root
kernels="${KERNELS:-exact,epick,double}"
out="${OUT:-$here/results/$(date -u +%F).csv}"

bench_check
bench_meshes "$@"
bench_workdir
mkdir -p "$(dirname "$out")"
bench_banner "KERNELS=$kernels"

for mesh in "${meshes[@]}"; do
  name="$(basename "${mesh%.*}")"
  if bench_skip "$name" "$mesh"; then continue; fi
  for view in ${views//,/ }; do
    for k in ${kernels//,/ }; do
      bench_hlr "$name" "$view" "$k" "$work/hlr_${name}_${view}_${k}" \
        surfaces "$mesh" --view "$view" --kernel "$k" \
        || { if [ "$k" = exact ]; then any_fail=1; fi; }
    done
  done
  bench_peer "$mesh" "$name"
done

BENCH_DIR="$bench_dir" "$py" - "$rows" "$work" "$out" "$views" <<'EOF'
import csv, os, sys
sys.path.insert(0, os.environ["BENCH_DIR"])
from common import load_hlr, load_peer, sec
rows_tsv, work, out, views = sys.argv[1:5]
order, hlr = load_hlr(rows_tsv)    # (mesh, view) -> {kernel: best stats or None}
peer = load_peer(work)

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
        run = lambda k: sec(ks[k]) if k in ks else "not run"  # KERNELS left it out
        row = [key[0], key[1], faces, sources, run("exact"), run("epick"), run("double"),
               "%.6f" % la if la is not None else "failed", ratio]
        w.writerow(row)
        st = ""
        if ex:
            g = ex["stage_seconds"]
            st = " / ".join("%.3f" % g.get(k, 0) for k in ("read", "sources", "sort", "write"))
        print("%-24s %-5s %7s %7s %10s %10s %10s %10s %8s | %s" % tuple(map(str, row + [st])))
print("\nwrote", out)
EOF

bench_done
