#!/bin/sh
# Draws every bundled scene (fixtures/scenes/*.off) in the iso and front views to SVG, DXF and JSON
# (and the iso view to PDF), and the filleted bracket with --smooth-edges thin, and runs the output checkers on the files (check_drawing.py: XML parse
# and rsvg-convert render, ezdxf's audit, pdfinfo and pdftoppm, hlr-lines/1 keys):
#   check_fixture_drawings.sh HLR CHECK_DRAWING_PY FIXTURES_DIR WORK_DIR
# Exits 77 (CTest: skipped) with the reason when a checker is missing.
set -eu
hlr=$1 checker=$2 fixtures=$3 work=$4

. "$(dirname "$0")/require_checkers.sh"

rm -rf "$work"
mkdir -p "$work"
for mesh in "$fixtures"/*.off; do
  stem=$(basename "$mesh" .off)
  for view in iso front; do
    "$hlr" draw "$mesh" --view "$view" -o "$work/${stem}_$view.svg" -o "$work/${stem}_$view.dxf" \
      -o "$work/${stem}_$view.json" >/dev/null
  done
  "$hlr" draw "$mesh" --view iso -o "$work/${stem}_iso.pdf" >/dev/null
done
# Smooth edges as thin lines (layer THIN, group thin): the filleted bracket, drawn and on a sheet.
bracket="$fixtures/../parts/filleted_bracket.off"
"$hlr" draw "$bracket" --view iso --smooth-edges thin -o "$work/filleted_bracket_thin.svg" \
  -o "$work/filleted_bracket_thin.dxf" -o "$work/filleted_bracket_thin.json" -o "$work/filleted_bracket_thin.pdf" >/dev/null
"$hlr" sheet "$bracket" --smooth-edges thin -o "$work/filleted_bracket_sheet.svg" \
  -o "$work/filleted_bracket_sheet.dxf" -o "$work/filleted_bracket_sheet.pdf" >/dev/null
exec /usr/bin/python3 "$checker" "$work"/*
