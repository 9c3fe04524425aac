#!/bin/sh
# Twenty vertices an ulp or a few apart around (0.5, 0.5) in a unit square, the diagonal
# (0,0)-(1,1) across the cluster and a segment from a cluster vertex to (1,1) (issue 47, item 6).
# The second segment leaves the cluster a few ulps off the diagonal and meets it at (1,1) at about
# 1e-15 radians: beyond the cluster the two bound a wedge narrower than an ulp over a length of 0.5.
# -pq30, -pq33.5 and -pq34 ran without end (1.4 GB in 30 s), splitting the wedge's subsegments down
# to two ulps along its length; the splits in a strip narrower than an ulp are refused now
# (BottomScale::in_strip_below_an_ulp, refine/bottom_scale.h). Each run must end (CTest's timeout), exit 0, pass
# deltri_mesh_verify and count its misses. The meshes had failed deltri_mesh_verify only because
# its walk along a segment was greedy: beyond the cluster the other segment's chain lies within
# the checker's 8-ulp tolerance of the diagonal, and the nearest vertex within it was a dead end;
# the walk now backtracks. At some bounds (-pq20, -pq30, -pq33.5, -pq34 here) the walk followed the
# other chain for the diagonal and then took the diagonal's own subsegment for an edge that must be
# locally Delaunay; the checker now takes every output subsegment that runs along an input segment
# (both ends on it within its tolerance) as constrained, so every run here must pass it outright.
#   ulp-cluster-wedge.sh DELTRI VERIFY
. "$(dirname "$0")/lib.sh"
cat >cluster.poly <<'POLY'
24 2 0 0
1 0 0
2 1 0
3 1 1
4 0 1
5 0.49999999999999972 0.49999999999999989
6 0.5 0.49999999999999994
7 0.49999999999999961 0.50000000000000011
8 0.49999999999999967 0.50000000000000022
9 0.49999999999999978 0.50000000000000011
10 0.49999999999999944 0.50000000000000022
11 0.49999999999999978 0.49999999999999994
12 0.5 0.50000000000000022
13 0.50000000000000056 0.49999999999999989
14 0.50000000000000022 0.49999999999999989
15 0.50000000000000089 0.49999999999999989
16 0.49999999999999961 0.49999999999999989
17 0.500000000000001 0.50000000000000022
18 0.49999999999999989 0.49999999999999994
19 0.50000000000000111 0.49999999999999989
20 0.49999999999999961 0.49999999999999994
21 0.5 0.50000000000000011
22 0.50000000000000111 0.50000000000000022
23 0.50000000000000011 0.50000000000000022
24 0.49999999999999978 0.5
6 0
1 1 2
2 2 3
3 3 4
4 4 1
5 1 3
6 19 3
0
POLY
# -pq20 to -pq22 ran without end: the bottom-scale splits of the other segment's chain crept
# along the wedge one lattice step at a time (edge floor 1.9e-34); a split whose half would join
# neighbouring doubles on a piece over 4,096 ulps long is refused now.
for q in -pq20 -pq21 -pq22 -pq30 -pq33.5 -pq34; do
  run 0 $q cluster.poly && counted_misses && verified cluster.poly cluster.1
done
echo "ok"
