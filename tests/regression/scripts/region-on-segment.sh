#!/bin/sh
# Issue 17 item 9: a region point exactly on a segment, or on a vertex a segment ends at, has no
# side: it is ignored with a warning, as hole points there are (before, the region's attribute and
# area bound went silently to the triangles of one side). A unit square split by a segment at
# y = 0.1 (the same double as the region points' y).
#   region-on-segment.sh DELTRI
set -u
deltri=$1
work=$(mktemp -d) || exit 1
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
fail=0
for at in "0.5 0.1" "0 0.1"; do
  printf '6 2 0 1\n1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n5 0 0.1 0\n6 1 0.1 0\n7 1\n1 1 2 1\n2 2 6 1\n3 6 3 1\n4 3 4 1\n5 4 5 1\n6 5 1 1\n7 5 6 1\n0\n1\n1 %s 7 0.001\n' "$at" > square.poly
  "$deltri" -pAaQ square.poly 2>stderr
  status=$?
  with7=$(awk 'NR > 1 && $5 == 7' square.1.ele | wc -l)
  echo "region point at ($at): exit $status, $with7 triangles with its attribute; $(cat stderr)"
  [ $status -eq 0 ] || { echo "FAIL: exit $status"; fail=1; }
  [ "$with7" -eq 0 ] || { echo "FAIL: the region point on a segment was used"; fail=1; }
  grep -q "1 region point lying exactly on a segment ignored" stderr || { echo "FAIL: no warning"; fail=1; }
done
# A region point on an edge without a segment is not ambiguous: it still applies.
printf '4 2 0 1\n1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n4 1\n1 1 2 1\n2 2 3 1\n3 3 4 1\n4 4 1 1\n0\n1\n1 0.5 0.5 7 0.001\n' > plain.poly
"$deltri" -pAQ plain.poly 2>stderr
left=$(awk 'NR > 1 && $5 != 7' plain.1.ele | wc -l)
[ "$left" -eq 0 ] && [ ! -s stderr ] || { echo "FAIL: a region point on an unconstrained edge was not applied to all ($left left)"; fail=1; }
[ $fail -eq 0 ] && echo ok
exit $fail
