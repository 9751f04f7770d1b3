#!/bin/sh
# Writes the sample drawings and runs the output checkers on them:
#   check_samples.sh EXPORT_TESTS CHECK_DRAWING_PY DIR
# Exits 77 (CTest: skipped) with the reason when a checker is missing.
set -eu
export_tests=$1 checker=$2 dir=$3

if ! [ -x /usr/bin/python3 ] || ! /usr/bin/python3 -c 'import ezdxf' 2>/dev/null; then
  echo "skipped: /usr/bin/python3 has no ezdxf (apt-get install python3-ezdxf)"
  exit 77
fi
if ! command -v rsvg-convert >/dev/null 2>&1; then
  echo "skipped: rsvg-convert is missing (apt-get install librsvg2-bin)"
  exit 77
fi

rm -rf "$dir"
"$export_tests" --write-samples "$dir"
exec /usr/bin/python3 "$checker" "$dir"/*
