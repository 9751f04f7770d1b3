#!/usr/bin/env bash
# Scaling (issue 12, goal 2): hlr draw, Blender's Line Art and OCC's PolyAlgo on assemblies of
# about 10k, 100k, 300k and 1M faces, in one run.
#
# usage (from anywhere; paths are relative to the repo root):
#   bench/scaling/run.sh
#
# For every size in SIZES it builds (once; kept in ASM_DIR, rebuilt when make_assembly.py is
# newer) the assembly ASM_DIR/asm_<size>_s<SEED>.off with bench/scaling/make_assembly.py: copies
# of the shared scene meshes on a 3D grid, moved by exact quarter turns, power-of-two scales and
# translations, overlapping each other in every view. Then, for every view in VIEWS, one after
# the other on the same file:
#   hlr draw ASM.off --view V --kernel exact [--threads HLR_THREADS] -o X.json
#       under /usr/bin/time (peak resident memory, CPU time), HLR_REPEAT times, under TIMEOUT
#       (bench/common.sh's bench_hlr);
#   ../shared/peers/blender_lineart/run.sh (Line Art, THREADS threads, REPEAT repeats), also
#       under /usr/bin/time (Blender's peak, its own ~150 MB included);
#   ../shared/peers/occ_hlr/run.sh with ALGOS=poly (HLRBRep_PolyAlgo), TIMEOUT=OCC_TIMEOUT;
#       once it has timed out on a size, the larger sizes are skipped ("skipped") unless OCC_ALL=1.
# and writes one CSV:
#   bench/scaling/results/<UTC date>.csv
# columns:
#   size, assembly, faces, copies, view, load1 (1-minute load average before the case),
#   feature_lines        stats.lines of hlr's JSON
#   hlr_s                stats.seconds: read + sources + sort + intersections + lines + precedence
#                        + write (the output stage up to the JSON's stats; older hlr builds have
#                        no write stage), least of HLR_REPEAT runs, or "failed"
#   hlr_status           ok, timeout, or how the run ended ("exited_with_non-zero_status_1",
#                        "terminated_by_signal_11", as /usr/bin/time saw it)
#   hlr_cpu_s            user + system CPU seconds of the whole hlr process (least over the
#                        repeats; includes start-up and writing the JSON): with 1 thread, far
#                        below hlr_s only when the machine was busy with something else
#   hlr_read_s ... hlr_write_s   stats.stage_seconds of that run, per stage (empty where the
#                        hlr build lacks the stage)
#   hlr_peak_kb          peak resident set of the hlr process (largest over the repeats), KiB;
#                        for a failed run, the peak until it ended
#   hlr_bytes_per_face   hlr_peak_kb * 1024 / faces (the whole process, start-up included)
#   hlr_us_per_face      hlr_s / faces, microseconds
#   welded_vertices      stats.welded_vertices (0: no copy shares a vertex with another)
#   lineart_s            the peer's lineart_seconds (Line Art's own timer, least of REPEAT runs;
#                        the OFF read and mesh build are not in it), or "failed"
#   lineart_us_per_face, lineart_peak_kb
#   ratio                hlr_s / lineart_s (> 1: hlr is slower)
#   occ_s                the OCC peer's hlr_s (median of OCC_REPEAT runs of PolyAlgo), or
#                        "timeout" / "error_rcN" / "skipped" / "absent"
#   occ_build_s          the OCC peer's build_s (mesh to sewn B-rep and triangulation; not in occ_s)
#   occ_us_per_face, occ_peak_kb
#   hlr_threads, lineart_threads
#   hlr_timeout_s, occ_timeout_s   TIMEOUT and OCC_TIMEOUT of the run (0: none), for the chart
# and prints the table, then how far the run is from the goals (time per face within 2x from the
# smallest to the largest size; 1M faces in at most 10 s; at most 1 KiB peak per input face).
# bench/scaling/chart.py CSV draws the chart (docs/images/scaling.svg and .png).
#
# env:
#   SIZES        comma list of face counts for make_assembly.py  (default 10k,100k,300k,1M)
#   SEED         make_assembly.py --seed                          (default 1)
#   ASM_DIR      where the assemblies are kept (not in git)       (default /tmp/hlr-scaling-asm)
#   VIEWS        comma list of views                              (default iso)
#   REPEAT       Line Art repeats (least is taken)                (default 5)
#   THREADS      Line Art threads                                 (default 1)
#   HLR_REPEAT   runs of each hlr command (least stats.seconds)   (default 1)
#   HLR_THREADS  hlr --threads N                                  (default: hlr's, every core)
#   TIMEOUT      seconds allowed per hlr run, 0 = none            (default 0); a timeout is "failed"
#   HLR          hlr binary                                       (default build/app/hlr)
#   LINEART=0    leave Line Art out;  OCC=0  leave OCC out
#   OCC_TIMEOUT  seconds per OCC run (B-rep build + PolyAlgo)     (default 300)
#   OCC_REPEAT   PolyAlgo runs per case (median)                  (default 1)
#   OCC_ALL=1    run OCC on every size, even after a timeout
#   OCC_BUILD    where the OCC peer program is built              (default ASM_DIR/occ_build)
#   PYTHON       python with numpy (JSON/CSV work, make_assembly) (default /usr/bin/python3)
#   OUT          CSV to write                                     (default bench/scaling/results/<UTC date>.csv)
#   KEEP=DIR     keep hlr's JSON (last run), stats, logs, memory figures and the peers' files
#                in DIR (default: a temp dir, removed at the end unless something failed)
# needs: a built hlr, python3-numpy, /usr/bin/time (apt-get install -y time), Blender
#   (apt-get install -y blender) and OCC (apt-get install -y libocct-modeling-algorithms-dev
#   libocct-modeling-data-dev libocct-foundation-dev libocct-data-exchange-dev) for the peers.
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
VIEWS="${VIEWS:-iso}"
source "$here/../common.sh"    # options, work folder, timed hlr runs, Line Art peer; cd to the root
out="${OUT:-$here/results/$(date -u +%F).csv}"
sizes="${SIZES:-10k,100k,300k,1M}"
seed="${SEED:-1}"
asm_dir="${ASM_DIR:-/tmp/hlr-scaling-asm}"
occ_peer="$root/../shared/peers/occ_hlr/run.sh"
occ_timeout="${OCC_TIMEOUT:-300}"
occ_repeat="${OCC_REPEAT:-1}"
occ_build="${OCC_BUILD:-$asm_dir/occ_build}"
if [ -n "${KEEP:-}" ]; then KEEP_HLR_JSON=1; fi

bench_check
[ -x /usr/bin/time ] || { echo "needs GNU time at /usr/bin/time for peak memory: apt-get install -y time" >&2; exit 1; }
"$py" -c "import numpy" 2>/dev/null || { echo "needs numpy for $py: apt-get install -y python3-numpy" >&2; exit 1; }
if [ "${LINEART:-1}" = 0 ]; then have_peer=0; fi
have_occ=0
if [ "${OCC:-1}" != 0 ]; then
  if [ ! -f "$occ_peer" ]; then echo "OCC peer $occ_peer absent: occ_s will be \"absent\"" >&2
  elif [ ! -d /usr/include/opencascade ]; then
    echo "OCC headers absent (apt-get install -y libocct-modeling-algorithms-dev libocct-modeling-data-dev libocct-foundation-dev libocct-data-exchange-dev): occ_s will be \"absent\"" >&2
  else have_occ=1; fi
fi
mkdir -p "$asm_dir" "$(dirname "$out")"
bench_workdir
bench_banner "SIZES=$sizes SEED=$seed OCC=$have_occ OCC_TIMEOUT=$occ_timeout (hlr draw, exact kernel)"

# hlr and the Line Art peer run through wrappers that add /usr/bin/time's peak memory (KiB) to
# the file named by $MEM_FILE; bench_hlr and bench_peer (bench/common.sh) run them as usual. The
# hlr wrapper applies TIMEOUT itself, inside /usr/bin/time (which then sees exit status 124), so
# that a timed-out run is told from a crash.
hlr_cmd="\"$hlr\""
if [ "$timeout_s" != 0 ]; then hlr_cmd="timeout $timeout_s $hlr_cmd"; fi
cat >"$work/hlr_timed" <<EOF
#!/bin/sh
exec /usr/bin/time -a -o "\$MEM_FILE" -f "%M %e %U %S" $hlr_cmd "\$@"
EOF
cat >"$work/peer_timed" <<EOF
#!/bin/sh
exec /usr/bin/time -a -o "\$MEM_FILE" -f "%M %e %U %S" bash "$peer" "\$@"
EOF
chmod +x "$work/hlr_timed" "$work/peer_timed"
hlr="$work/hlr_timed"
peer="$work/peer_timed"
hlr_timeout="$timeout_s"; timeout_s=0    # bench_hlr: no timeout of its own

# the OCC peer builds its program on first use: do that now, outside the timed runs
if [ "$have_occ" = 1 ] && [ ! -x "$occ_build/occ_hlr" ]; then
  echo "building the OCC peer in $occ_build"
  BUILD="$occ_build" KEEP="$work/occ_warmup" ALGOS=poly REPEAT=1 \
    bash "$occ_peer" "$work/occ_warmup.csv" front "$scenes/joint.off" >/dev/null \
    || { echo "OCC peer build failed: occ_s will be \"absent\"" >&2; have_occ=0; }
fi

cases="$work/cases.tsv"    # size assembly faces copies view load1 hlr-mem peer-mem occ-csv occ-mem
: >"$cases"
occ_timed_out=0
for size in ${sizes//,/ }; do
  name="asm_${size}_s${seed}"
  asm="$asm_dir/$name.off"
  if [ ! -s "$asm" ] || [ "$here/make_assembly.py" -nt "$asm" ]; then
    "$py" "$here/make_assembly.py" "$size" -o "$asm" --seed "$seed" --scenes "$scenes"
  else
    cat "$asm.txt"
  fi
  copies="$(sed -n 's/.* \([0-9]*\) copies on .*/\1/p' "$asm.txt")"
  asm_faces="$(sed -n '2p' "$asm" | cut -d' ' -f2)"
  for view in ${views//,/ }; do
    case_base="$work/${name}_${view}"
    load1="$(cut -d' ' -f1 /proc/loadavg)"
    echo "== $name $view: hlr (load $load1)"
    MEM_FILE="$case_base.hlr_mem" bench_hlr "$name" "$view" exact "$work/hlr_${name}_${view}" \
      draw "$asm" --view "$view" --kernel exact || any_fail=1
    if [ "$have_peer" = 1 ]; then
      echo "== $name $view: Line Art"
      views="$view" MEM_FILE="$case_base.peer_mem" bench_peer "$asm" "${name}_${view}"
    fi
    occ_csv=""
    if [ "$have_occ" = 1 ]; then
      occ_csv="$work/occ_${name}_${view}.csv"
      if [ "$occ_timed_out" = 1 ] && [ "${OCC_ALL:-0}" != 1 ]; then
        echo "== $name $view: OCC skipped (timed out on a smaller size)"
        printf 'mesh,faces,view,algo,build_s,hlr_s,vis_len,hid_len,status\n%s,,%s,poly,,,,,skipped\n' \
          "$name" "$view" >"$occ_csv"
      else
        echo "== $name $view: OCC PolyAlgo (timeout $occ_timeout s)"
        /usr/bin/time -a -o "$case_base.occ_mem" -f "%M %e %U %S" \
          env BUILD="$occ_build" KEEP="$work/occ" ALGOS=poly REPEAT="$occ_repeat" TIMEOUT="$occ_timeout" \
          bash "$occ_peer" "$occ_csv" "$view" "$asm" || echo "OCC peer failed on $name $view" >&2
        if grep -q ',timeout$' "$occ_csv" 2>/dev/null; then occ_timed_out=1; fi
      fi
    fi
    printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$size" "$name" "$asm_faces" "$copies" "$view" "$load1" \
      "$case_base.hlr_mem" "$case_base.peer_mem" "$occ_csv" "$case_base.occ_mem" >>"$cases"
  done
done

BENCH_DIR="$bench_dir" HLR_THREADS_USED="${hlr_threads:-default}" LINEART_THREADS="$threads" \
  HLR_TIMEOUT="$hlr_timeout" OCC_TIMEOUT="$occ_timeout" \
  "$py" - "$rows" "$cases" "$work" "$out" <<'EOF'
import csv, os, sys
sys.path.insert(0, os.environ["BENCH_DIR"])
from common import load_hlr, load_peer, sec
rows_tsv, cases_tsv, work, out = sys.argv[1:5]
_, hlr = load_hlr(rows_tsv)     # (assembly, view) -> {"exact": best stats or None}
peer = load_peer(work)          # (assembly, view) -> Line Art row
stages = ["read", "sources", "sort", "intersections", "lines", "precedence", "write"]

def timed(path):
    """The runs /usr/bin/time wrote to path: (peak KiB, wall s, CPU s = user + system) each,
    one line per run (a failed run has a status line before its figures)."""
    runs = []
    try:
        for l in open(path):
            t = l.split()
            if len(t) == 4 and t[0].isdigit():
                runs.append((int(t[0]), float(t[1]), float(t[2]) + float(t[3])))
    except OSError:
        pass
    return runs

def peak_kb(path):
    """Largest peak over the runs, KiB, or None."""
    runs = timed(path)
    return max(r[0] for r in runs) if runs else None

def hlr_status(ex, path):
    """ok, timeout (exit 124 of the wrapper's timeout), or how /usr/bin/time saw hlr end."""
    if ex:
        return "ok"
    try:
        text = open(path).read()
    except OSError:
        return "failed"
    if "non-zero status 124" in text:
        return "timeout"
    for l in text.splitlines():
        if l.startswith("Command "):
            return l.replace("Command ", "").replace(" ", "_")
    return "failed"

def f6(x):
    return "%.6f" % x if x is not None else ""

def per_face(s, faces, scale=1e6):
    return "%.3f" % (s * scale / faces) if (s is not None and faces) else "n/a"

cols = (["size", "assembly", "faces", "copies", "view", "load1", "feature_lines", "hlr_s", "hlr_status",
         "hlr_cpu_s"]
        + ["hlr_%s_s" % s for s in stages]
        + ["hlr_peak_kb", "hlr_bytes_per_face", "hlr_us_per_face", "welded_vertices",
           "lineart_s", "lineart_us_per_face", "lineart_peak_kb", "ratio",
           "occ_s", "occ_build_s", "occ_us_per_face", "occ_peak_kb", "hlr_threads", "lineart_threads",
           "hlr_timeout_s", "occ_timeout_s"])
table = []
with open(out, "w", newline="") as f:
    w = csv.writer(f)
    w.writerow(cols)
    for line in open(cases_tsv):
        size, name, asm_faces, copies, view, load1, hmem, pmem, occ_csv, omem = line.rstrip("\n").split("\t")
        ex = hlr.get((name, view), {}).get("exact")
        pr = peer.get((name, view))
        occ = next(iter(csv.DictReader(open(occ_csv))), None) if occ_csv and os.path.exists(occ_csv) else None
        faces = ex["faces"] if ex else int(asm_faces)
        hs = ex["seconds"] if ex else None
        la = float(pr["lineart_seconds"]) if pr else None
        hk = peak_kb(hmem)     # also for a failed run: the peak until it ended
        hcpu = min((r[2] for r in timed(hmem)), default=None) if ex else None
        if occ is None:
            occ_s, occ_b, occ_v = "absent", "", None
        elif occ["status"] == "ok":
            occ_v = float(occ["hlr_s"]); occ_s = "%.5f" % occ_v; occ_b = occ["build_s"]
        else:
            occ_s, occ_b, occ_v = occ["status"], "", None
        g = ex.get("stage_seconds", {}) if ex else {}
        row = ([size, name, faces or "", copies, view, load1, ex["lines"] if ex else "", sec(ex),
                hlr_status(ex, hmem), "%.2f" % hcpu if hcpu is not None else ""]
               + [f6(g.get(s)) if ex else "failed" for s in stages]
               + [hk if hk is not None else "", "%.0f" % (hk * 1024 / faces) if (hk and faces) else "n/a",
                  per_face(hs, faces), ex.get("welded_vertices", "") if ex else "",
                  f6(la) if pr else "failed", per_face(la, faces), peak_kb(pmem) or "",
                  "%.2f" % (hs / la) if (hs is not None and la) else "n/a",
                  occ_s, occ_b, per_face(occ_v, faces), peak_kb(omem) or "" if occ_v else "",
                  os.environ["HLR_THREADS_USED"], os.environ["LINEART_THREADS"],
                  os.environ["HLR_TIMEOUT"], os.environ["OCC_TIMEOUT"] if occ else ""])
        w.writerow(row)
        table.append((faces, view, hs, hk, la, occ_s, row))

fmt = "%-10s %-5s %9s %9s %9s %9s %9s %9s %6s %12s"
print("\n" + fmt % ("faces", "view", "hlr_s", "us/face", "B/face", "peak_MiB", "lineart_s", "la_us/f",
                    "ratio", "occ_s"))
for faces, view, hs, hk, la, occ_s, row in table:
    print(fmt % (faces, view, "%.3f" % hs if hs is not None else "failed", row[cols.index("hlr_us_per_face")],
                 row[cols.index("hlr_bytes_per_face")], "%.1f" % (hk / 1024) if hk else "n/a",
                 "%.3f" % la if la is not None else "failed", row[cols.index("lineart_us_per_face")],
                 row[cols.index("ratio")], occ_s))

# the goals of issue 12 (goal 2), per view
for view in sorted({t[1] for t in table}):
    ok = [t for t in table if t[1] == view and t[2] is not None and t[0]]
    if not ok:
        continue
    us = [t[2] * 1e6 / t[0] for t in ok]
    big = max(ok, key=lambda t: t[0])
    print("\ngoals, %s view:" % view)
    print("  time per face, smallest to largest size: %.1f .. %.1f us (max/min %.2f; goal <= 2)"
          % (us[0], us[-1], max(us) / min(us)))
    print("  largest (%d faces): %.1f s (goal for 1M faces: <= 10 s on 2 cores; hlr threads: %s)"
          % (big[0], big[2], os.environ["HLR_THREADS_USED"]))
    print("  peak memory per face at the largest: %s bytes (goal <= 1024)"
          % big[6][cols.index("hlr_bytes_per_face")])
print("\nwrote", out)
EOF

bench_done
