#!/bin/sh
# Draws the two-part scene of tests/cli/parts/ (a cube and a box behind it whose left and top edges
# lie 1e-7 inside the cube's outline in the front view) to SVG, DXF and JSON in the front and iso
# views, and runs the output checkers with the scene's parts (check_drawing.py --parts): one layer
# pair per part in the DXF, one group per part and class in the SVG.
#   check_part_drawings.sh HLR CHECK_DRAWING_PY PARTS_DIR WORK_DIR
# Exits 77 (CTest: skipped) with the reason when a checker is missing.
set -eu
hlr=$1 checker=$2 parts=$3 work=$4

. "$(dirname "$0")/require_checkers.sh"

rm -rf "$work"
mkdir -p "$work"
for view in front iso; do
  "$hlr" draw "$parts/front_box.off" "$parts/back_box.off" --view "$view" -o "$work/parts_$view.svg" \
    -o "$work/parts_$view.dxf" -o "$work/parts_$view.json" >/dev/null
done
exec /usr/bin/python3 "$checker" --parts front_box,back_box "$work"/*
