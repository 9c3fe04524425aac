#!/bin/sh
# A strip narrower than an ulp between two segments (issue 47, item 8, what the lopped diamond left
# behind): the diamond's segment from (1/3, 0) to (2.6666666666666665, 4.08e-17) runs over the
# vertices (1,0) and (2,0) of a collinear chain a fraction of an ulp below it. Each side's vertices
# encroach upon the other's subsegments, and the splits went on down to subsegments of two ulps
# along the whole strip (about 1e16 of them; the feature floor there is 6e-36). Such splits are
# refused now (BottomScale::in_strip_below_an_ulp, refine/bottom_scale.h): each run ends (CTest's timeout), exits 0, passes
# deltri_mesh_verify and counts the triangles left in the strip.
#   sub-ulp-strip.sh DELTRI VERIFY
. "$(dirname "$0")/lib.sh"
cat >strip.poly <<'POLY'
8 2 0 0
1 0 0
2 1.5 1
3 3 0
4 1.5 -1
5 1 0
6 2 0
7 0.33333333333333331 0
8 2.6666666666666665 4.0821559971578442e-17
10 0
1 1 2
2 2 3
3 3 4
4 4 1
5 1 5
6 5 6
7 6 3
8 1 7
9 7 8
10 8 3
0
POLY
for q in -pq20 -pq30 -pq34; do
  ends_counted strip.poly strip.1 $q strip.poly
done
echo "ok"
