# Sourced by the scripts that run check_drawing.py: exits 77 (CTest: skipped) with the reason when
# an output checker is missing.
if ! [ -x /usr/bin/python3 ] || ! /usr/bin/python3 -c 'import ezdxf' 2>/dev/null; then
  echo "skipped: /usr/bin/python3 has no ezdxf (apt-get install python3-ezdxf)"
  exit 77
fi
if ! command -v rsvg-convert >/dev/null 2>&1; then
  echo "skipped: rsvg-convert is missing (apt-get install librsvg2-bin)"
  exit 77
fi
if ! command -v pdfinfo >/dev/null 2>&1 || ! command -v pdftoppm >/dev/null 2>&1; then
  echo "skipped: pdfinfo or pdftoppm is missing (apt-get install poppler-utils)"
  exit 77
fi
