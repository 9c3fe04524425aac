#!/bin/sh
# A size bound met (called by CTest, see cases.cmake):  area_bound.sh DELTRI INPUT SWITCHES AREA
# deltri SWITCHES INPUT must exit 0 with nothing on stderr, and every triangle's area, computed
# here from the files, must be at most AREA. For inputs the mesh verifier cannot check once
# refined (a point set's hull split at rounded points).
set -u
deltri=$1 input=$2 switches=$3 area=$4
here=$(cd "$(dirname "$0")" && pwd)
. "$here/measure.sh"
run_in_scratch "$deltri" "$input" "$switches"
[ -s err ] && { echo "FAIL: deltri $switches $file warned:"; cat err; exit 1; }
set -- $(measure "${file%.*}.1")
awk -v a="$2" -v bound="$area" 'BEGIN { exit !(a <= bound) }' || { echo "FAIL: largest area $2 > $area"; exit 1; }
echo "deltri $switches $file: largest area $2 <= $area"
