#!/bin/sh
# Bounds met (called by CTest, see cases.cmake):  quality_bound.sh DELTRI INPUT SWITCHES ANGLE [AREA]
# deltri SWITCHES INPUT must exit 0 without reporting triangles that miss the bounds, and every
# angle, computed here from the files, must be at least ANGLE degrees (every area at most AREA).
# For point sets refined at the bottom of double precision, whose hulls the mesh verifier cannot
# check once split at rounded points.
set -u
deltri=$1 input=$2 switches=$3 angle=$4 area=${5:-}
here=$(cd "$(dirname "$0")" && pwd)
. "$here/measure.sh"
run_in_scratch "$deltri" "$input" "$switches"
grep -q "miss the requested bounds" err && { echo "FAIL: deltri $switches $file left triangles:"; cat err; exit 1; }
set -- $(measure "${file%.*}.1")
awk -v a="$1" -v bound="$angle" 'BEGIN { exit !(a >= bound) }' || { echo "FAIL: smallest angle $1 < $angle"; exit 1; }
if [ -n "$area" ]; then
  awk -v a="$2" -v bound="$area" 'BEGIN { exit !(a <= bound) }' || { echo "FAIL: largest area $2 > $area"; exit 1; }
fi
echo "deltri $switches $file: smallest angle $1 >= $angle, largest area $2"
