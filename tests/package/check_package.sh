#!/bin/sh
# Installs hlr from BUILD into a prefix, builds examples/draw_part out of tree against it with
# find_package(hlr), and checks that it draws the bundled anchor as the in-tree build does.
# usage: check_package.sh BUILD SOURCE WORK IN_TREE_DRAW_PART
set -eu
build=$1 source=$2 work=$3 in_tree=$4
rm -rf "$work/prefix" "$work/out"
mkdir -p "$work/out"
cmake --install "$build" --prefix "$work/prefix" >/dev/null
test -f "$work/prefix/lib/cmake/hlr/hlrConfig.cmake"
test -x "$work/prefix/bin/hlr"
launcher=
command -v ccache >/dev/null && launcher=-DCMAKE_CXX_COMPILER_LAUNCHER=ccache
cmake -S "$source/examples" -B "$work/examples" -G Ninja -DCMAKE_PREFIX_PATH="$work/prefix" \
  -DHLR_EXAMPLES=draw_part $launcher >/dev/null
cmake --build "$work/examples" >/dev/null
"$work/examples/draw_part" "$source/fixtures/parts/anchor.off" "$work/out/installed.svg" front 2>/dev/null
"$in_tree" "$source/fixtures/parts/anchor.off" "$work/out/in_tree.svg" front 2>/dev/null
cmp "$work/out/installed.svg" "$work/out/in_tree.svg"
echo "package_out_of_tree: draw_part built against $work/prefix draws what the in-tree build draws"
