#!/bin/sh
# The CAD fixtures' drawings with true curves (CIRCLE, ARC, ELLIPSE; SVG and PDF arcs) through
# the output checkers: ezdxf's audit, the SVG rendered, the PDF read (tests/tools/check_drawing.py).
# usage: check_cad_drawings.sh HLR CAD_FIXTURES CHECK_DRAWING_PY DIR   (exit 77: no ezdxf)
hlr="$1" fixtures="$2" check="$3" dir="$4"
/usr/bin/python3 -c 'import ezdxf' 2>/dev/null || exit 77
rm -rf "$dir" && mkdir -p "$dir" && "$fixtures" "$dir" || exit 1
files=""
for part in plate flange; do
  for view in top iso; do
    base="$dir/${part}_$view"
    "$hlr" draw "$dir/$part.step" --view "$view" -o "$base.dxf" -o "$base.svg" -o "$base.pdf" >/dev/null || exit 1
    files="$files $base.dxf $base.svg $base.pdf"
  done
  "$hlr" sheet "$dir/$part.step" --views front,top,right,iso -o "$dir/${part}_sheet.dxf" -o "$dir/${part}_sheet.svg" >/dev/null || exit 1
  files="$files $dir/${part}_sheet.dxf $dir/${part}_sheet.svg"
done
# Slanted circles are ELLIPSE entities in the iso views.
grep -qx "ELLIPSE" "$dir/plate_iso.dxf" || { echo "FAIL $dir/plate_iso.dxf: no ELLIPSE"; exit 1; }
# shellcheck disable=SC2086
/usr/bin/python3 "$check" $files
