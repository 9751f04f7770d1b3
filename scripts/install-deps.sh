#!/usr/bin/env bash
# Installs the Debian packages hlr needs to build, test and benchmark. Idempotent, non-interactive:
# only packages that are missing are installed, so a second run does nothing and needs no network.
set -euo pipefail

packages=(
  # build
  build-essential cmake ninja-build ccache pkg-config
  # libraries (DESIGN.md "Dependencies")
  libcgal-dev libgmp-dev libmpfr-dev libboost-dev
  libopenmesh-dev libglm-dev libtbb-dev libcli11-dev nlohmann-json3-dev
  # allocator of the hlr program (app/CMakeLists.txt): tcmalloc_minimal
  libgoogle-perftools-dev
  # the sun's position for hlr shadows --sun-at (kernel/src/sun.cpp)
  libnova-dev
  # STEP, IGES and B-rep input (cad/): OpenCASCADE's readers, BRepMesh and XCAF; data-exchange-dev
  # brings headers the modelling packages need (NCollection_AliasedArray.hxx)
  libocct-foundation-dev libocct-modeling-data-dev libocct-modeling-algorithms-dev
  libocct-ocaf-dev libocct-data-exchange-dev
  # DXF, PNG and PDF writers (export/)
  libdxflib-dev libpng-dev libcairo2-dev
  # tests and benchmarks
  libgtest-dev libgmock-dev librapidcheck-dev libbenchmark-dev
  # SVG read back in export/tests
  libexpat1-dev
  # output checkers (tests/tools/check_drawing.py: DXF audit, SVG rendering, PDF read back)
  python3-ezdxf librsvg2-bin poppler-utils
  # the speed-versus-accuracy chart (bench/chart)
  python3-matplotlib
  # peer in the clipper benchmark (Clipper 1, integer coordinates)
  libpolyclipping-dev
  # the Python module hlrdraw (python/): bindings, numpy arrays, its tests (pytest, Hypothesis with
  # shapely as the clipper's oracle) and batches on Dask (python3 -m hlrdraw.batch)
  pybind11-dev python3-dev python3-numpy python3-pytest python3-hypothesis python3-shapely python3-distributed
  # fuzzing (scripts/fuzz.sh): clang's libFuzzer and sanitizers
  clang libfuzzer-14-dev
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

echo "install-deps: installing ${missing[*]}"
sudo_cmd=()
[ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
