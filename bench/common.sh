# Shared by the bench/*/run.sh scripts (hlr beside Blender's Line Art). Sourced, not run.
#
# The sourcing script runs under `set -euo pipefail`. Sourcing this file reads the options from
# the environment, with these defaults:
#   VIEWS=front,top,right,iso  SKIP=  REPEAT=5 (peer)  HLR_REPEAT=1  THREADS=1 (peer)
#   HLR_THREADS= (hlr --threads; default: hlr's own, every core)
#   TIMEOUT=0 (per hlr run, 0 = none)  HLR=build/app/hlr  PYTHON=/usr/bin/python3  KEEP=DIR
# and sets: root (repo root, also the current folder), views, skip, repeat, hlr_repeat, threads,
# timeout_s, hlr, py, peer, scenes, bench_dir. The functions below do the rest:
#   bench_check              checks hlr and python (exit 1) and the peer (sets have_peer=0/1)
#   bench_meshes [MESH...]   sets the array meshes: the arguments, else ../shared/scenes/*.off
#                            (exits 0 when there is none)
#   bench_workdir            sets work (KEEP or a temp dir), keep, rows (a TSV), any_fail=0
#   bench_banner EXTRA       prints the hlr binary, the peer and the options
#   bench_skip NAME MESH     true (0) when the mesh is absent or named in SKIP (and says so)
#   bench_hlr NAME VIEW TAG BASE HLR-ARGS...
#                            runs `hlr HLR-ARGS -o BASE.json` HLR_REPEAT times (under TIMEOUT),
#                            appends each run's stats (bench/common.py stats) to BASE.stats, and
#                            a row "NAME VIEW TAG ok|failed BASE.stats" to $rows; returns 1 when a
#                            run failed. BASE.json is removed unless KEEP_HLR_JSON=1 (then the
#                            last run's JSON stays).
#   bench_peer MESH NAME     runs the peer on one mesh and all views into $work/peer_NAME.csv
#                            (sets any_fail=1 on failure)
#   bench_done               removes the temp work folder unless KEEP or a failure
# bench/common.py reads the rows and the peer CSVs back (load_hlr, load_peer).

bench_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$bench_dir/.." && pwd)"
cd "$root"

views="${VIEWS:-front,top,right,iso}"
skip=",${SKIP:-},"
repeat="${REPEAT:-5}"
hlr_repeat="${HLR_REPEAT:-1}"
threads="${THREADS:-1}"
hlr_threads="${HLR_THREADS:-}"
timeout_s="${TIMEOUT:-0}"
hlr="${HLR:-$root/build/app/hlr}"
py="${PYTHON:-/usr/bin/python3}"
peer="$root/../shared/peers/blender_lineart/run.sh"
scenes="$root/../shared/scenes"

bench_check() {
  [ -x "$hlr" ] || { echo "no hlr binary at $hlr (build the project first)" >&2; exit 1; }
  [ -x "$py" ] || { echo "no python at $py" >&2; exit 1; }
  have_peer=1
  if [ ! -f "$peer" ]; then echo "peer script $peer absent: lineart_s will be \"failed\"" >&2; have_peer=0; fi
  if [ "$have_peer" = 1 ] && ! command -v blender >/dev/null; then
    echo "blender not installed (apt-get install -y blender): lineart_s will be \"failed\"" >&2; have_peer=0
  fi
}

bench_meshes() {
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
}

bench_workdir() {
  if [ -n "${KEEP:-}" ]; then work="$KEEP"; mkdir -p "$work"; keep=1; else work="$(mktemp -d)"; keep=0; fi
  rows="$work/rows.tsv"          # mesh view tag status stats-file
  : >"$rows"
  any_fail=0
}

bench_banner() {
  echo "hlr: $hlr ($(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo '?'))"
  echo "peer: $([ "$have_peer" = 1 ] && blender -b --version 2>/dev/null | head -1 || echo absent), REPEAT=$repeat THREADS=$threads"
  echo "HLR_REPEAT=$hlr_repeat TIMEOUT=$timeout_s VIEWS=$views SKIP=${SKIP:-} $*"
  echo "machine: $(nproc) cores, $(uptime | sed 's/.*load/load/')"
  # Something else on the cores skews every time: a benchmark run once went through, unnoticed,
  # beside a test left running (docs/BENCHMARKS.md, "Fifteenth run").
  local busy
  busy=$(awk '{split($4, r, "/"); print r[1] - 1}' /proc/loadavg 2>/dev/null || echo 0)
  if [ "${busy:-0}" -gt 0 ]; then
    echo "warning: $busy other processes are running now (/proc/loadavg): the times will be off" >&2
  fi
  echo "work: $work"
}

bench_skip() {
  if [ ! -f "$2" ]; then echo "skip $1: $2 absent" >&2; return 0; fi
  if [[ "$skip" == *",$1,"* ]]; then echo "skip $1 (SKIP)"; return 0; fi
  return 1
}

bench_hlr() {
  local name="$1" view="$2" tag="$3" base="$4"; shift 4
  local cmd=("$hlr" "$@" ${hlr_threads:+--threads "$hlr_threads"} -o "$base.json") status=ok r rc
  if [ "$timeout_s" != 0 ]; then cmd=(timeout "$timeout_s" "${cmd[@]}"); fi
  : >"$base.stats"
  for ((r = 1; r <= hlr_repeat; r++)); do
    rm -f "$base.json"
    if "${cmd[@]}" >"$base.log" 2>&1 && [ -s "$base.json" ]; then
      # keep only the stats, one JSON line per repeat (the geometry can be large)
      "$py" "$bench_dir/common.py" stats "$base.json" >>"$base.stats"
    else
      rc=$?; status=failed
      echo "hlr $tag failed on $name $view (exit $rc; log: $base.log)" >&2
      break
    fi
  done
  if [ "${KEEP_HLR_JSON:-0}" != 1 ]; then rm -f "$base.json"; fi
  printf '%s\t%s\t%s\t%s\t%s\n' "$name" "$view" "$tag" "$status" "$base.stats" >>"$rows"
  [ "$status" = ok ]
}

bench_peer() {
  local mesh="$1" name="$2"
  [ "$have_peer" = 1 ] || return 0
  mkdir -p "$work/peer"
  THREADS="$threads" REPEAT="$repeat" KEEP="$work/peer" bash "$peer" "$work/peer_${name}.csv" "$views" "$mesh" \
    || { echo "peer run failed on $name" >&2; any_fail=1; }
}

bench_done() {
  if [ "$keep" = 0 ] && [ "$any_fail" = 0 ]; then rm -rf "$work"; else echo "kept $work"; fi
}
