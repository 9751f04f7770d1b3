#!/usr/bin/env bash
# Interleaved A/B of two hlr binaries on the scaling assemblies (issue 12), with Blender's Line Art
# once per size in the same run: what docs/BENCHMARKS.md's before/after tables of the assemblies
# come from. Per size, ROUNDS rounds, the two binaries' order alternating from round to round:
#   hlr draw ASM --view VIEW --threads THREADS -o X.json     under /usr/bin/time (peak KiB)
# then THREADS=THREADS REPEAT=1 ../shared/peers/blender_lineart/run.sh on the same file.
#
# usage (from anywhere): BEFORE=/tmp/hlr-old AFTER=/tmp/hlr-new bench/scaling/ab.sh
# env: SIZES (default "10k 100k 300k 1M"), ROUNDS (default 2; 1 from 300k on), VIEW (iso),
#      THREADS (1), ASM_DIR (/tmp/hlr-scaling-asm: assemblies made once by make_assembly.py,
#      seed 1), OUT (bench/scaling/results/<UTC date>-ab.csv), LINEART=0 to leave the peer out.
# writes one CSV row per run: size, faces, round, binary (before|after), stats.seconds, the
# stage seconds, peak KiB, load1; then per size whether both drew the same lines, and the peer's
# lineart_seconds. Needs python3-numpy, /usr/bin/time and, for the peer, Blender.
set -euo pipefail
cd "$(dirname "$0")/../.."
: "${BEFORE:?BEFORE=path of the old hlr binary}" "${AFTER:?AFTER=path of the new hlr binary}"
sizes="${SIZES:-10k 100k 300k 1M}"
view="${VIEW:-iso}"
threads="${THREADS:-1}"
asm_dir="${ASM_DIR:-/tmp/hlr-scaling-asm}"
out="${OUT:-bench/scaling/results/$(date -u +%F)-ab.csv}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
mkdir -p "$asm_dir" "$(dirname "$out")"
echo "size,faces,round,binary,seconds,read,sources,sort,intersections,lines,precedence,write,peak_kb,load1" >"$out"

run() {  # size asm round name binary
  /usr/bin/time -f %M -o "$work/time" "$5" draw "$2" --view "$view" --threads "$threads" -o "$work/$4.json" \
    >/dev/null 2>"$work/err" || { echo "$1,,$3,$4,failed: $(tail -1 "$work/err")" >>"$out"; return; }
  /usr/bin/python3 - "$work/$4.json" "$1" "$3" "$4" "$(cat "$work/time")" >>"$out" <<'PY'
import json, os, sys
doc = json.load(open(sys.argv[1])); s = doc["stats"]; t = s["stage_seconds"]
stages = ("read", "sources", "sort", "intersections", "lines", "precedence", "write")
faces = doc.get("input", {}).get("faces", "")
print(",".join([sys.argv[2], str(faces), sys.argv[3], sys.argv[4], "%.3f" % s["seconds"]] +
               ["%.3f" % t.get(k, 0) for k in stages] + [sys.argv[5], "%.2f" % os.getloadavg()[0]]))
PY
}

for size in $sizes; do
  asm="$asm_dir/asm_${size}_s1.off"
  [ -s "$asm" ] || /usr/bin/python3 bench/scaling/make_assembly.py "$size" -o "$asm" --seed 1 >/dev/null
  rounds="${ROUNDS:-2}"
  case "$size" in 10k|100k) ;; *) rounds=1 ;; esac
  for r in $(seq 1 "$rounds"); do
    if [ $((r % 2)) -eq 1 ]; then run "$size" "$asm" "$r" before "$BEFORE"; run "$size" "$asm" "$r" after "$AFTER"
    else run "$size" "$asm" "$r" after "$AFTER"; run "$size" "$asm" "$r" before "$BEFORE"; fi
  done
  /usr/bin/python3 -c "
import json, sys
a, b = (json.load(open(f))['lines'] for f in sys.argv[1:3])
print('$size,lines_equal,' + str(a == b))" "$work/before.json" "$work/after.json" >>"$out"
  if [ "${LINEART:-1}" != 0 ]; then
    THREADS="$threads" REPEAT=1 ../shared/peers/blender_lineart/run.sh "$work/peer.csv" "$view" "$asm" >/dev/null 2>&1 &&
      echo "$size,lineart_seconds,$(tail -1 "$work/peer.csv" | cut -d, -f4)" >>"$out" ||
      echo "$size,lineart_seconds,failed" >>"$out"
  fi
done
echo "wrote $out"
