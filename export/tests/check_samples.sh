#!/bin/sh
# Writes the sample drawings and runs the output checkers on them:
#   check_samples.sh EXPORT_TESTS CHECK_DRAWING_PY DIR
# Exits 77 (CTest: skipped) with the reason when a checker is missing.
set -eu
export_tests=$1 checker=$2 dir=$3

. "$(dirname "$checker")/require_checkers.sh"

rm -rf "$dir"
"$export_tests" --write-samples "$dir"
# parts.*: three parts (bolt, bolt-2, nut; see three_parts() in lines_writers_test.cpp).
status=0
/usr/bin/python3 "$checker" $(ls "$dir"/* | grep -v '/parts\.') || status=1
/usr/bin/python3 "$checker" --parts bolt,bolt-2,nut "$dir"/parts.* || status=1
exit $status
