#!/bin/sh
# Draws every bundled scene (fixtures/scenes/*.off) in the iso and front views to SVG, DXF and JSON
# and runs the output checkers on the files (check_drawing.py: XML parse and rsvg-convert render,
# ezdxf's audit, hlr-lines/1 keys):
#   check_fixture_drawings.sh HLR CHECK_DRAWING_PY FIXTURES_DIR WORK_DIR
# Exits 77 (CTest: skipped) with the reason when a checker is missing.
set -eu
hlr=$1 checker=$2 fixtures=$3 work=$4

if ! [ -x /usr/bin/python3 ] || ! /usr/bin/python3 -c 'import ezdxf' 2>/dev/null; then
  echo "skipped: /usr/bin/python3 has no ezdxf (apt-get install python3-ezdxf)"
  exit 77
fi
if ! command -v rsvg-convert >/dev/null 2>&1; then
  echo "skipped: rsvg-convert is missing (apt-get install librsvg2-bin)"
  exit 77
fi

rm -rf "$work"
mkdir -p "$work"
for mesh in "$fixtures"/*.off; do
  stem=$(basename "$mesh" .off)
  for view in iso front; do
    "$hlr" draw "$mesh" --view "$view" -o "$work/${stem}_$view.svg" -o "$work/${stem}_$view.dxf" \
      -o "$work/${stem}_$view.json" >/dev/null
  done
done
exec /usr/bin/python3 "$checker" "$work"/*
