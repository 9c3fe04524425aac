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
# the walk now backtracks. At some bounds (-pq20, -pq30, -pq33.5, -pq34 here) the checker still
# follows the other chain for the diagonal and then takes the diagonal's own subsegment for an
# edge that is not locally Delaunay; such rejections are checked against the output's
# subsegments (verified_but_subsegments).
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
# verified_but_subsegments INPUT OUTBASE: OUTBASE passes deltri_mesh_verify, or every rejection is
# an edge "not locally Delaunay" that OUTBASE.poly lists as a subsegment (a constrained Delaunay
# triangulation need not be Delaunay across its subsegments): the checker's walk can take the
# other chain for the diagonal and then miss the diagonal's own subsegments.
verified_but_subsegments() {
  "$verify" --input "$1" --mesh "$2" --refined >verify.out 2>&1 && return 0
  [ -s verify.out ] || fail "$2: deltri_mesh_verify failed without a message"
  while read -r line; do
    pair=$(echo "$line" | sed -n 's/^delaunay: edge \([0-9]*\)-\([0-9]*\) is not locally Delaunay$/\1 \2/p')
    [ -n "$pair" ] || fail "$2 does not pass deltri_mesh_verify: $line"
    set -- "$1" "$2" $pair
    awk -v a="$3" -v b="$4" 'NR > 2 && NF >= 3 && (($2 == a && $3 == b) || ($2 == b && $3 == a)) { found = 1 }
      END { exit !found }' "$2.poly" || fail "$2: edge $3-$4 is not locally Delaunay and not a subsegment"
  done <verify.out
}
# -pq20 to -pq22 ran without end: the bottom-scale splits of the other segment's chain crept
# along the wedge one lattice step at a time (edge floor 1.9e-34); a split whose half would join
# neighbouring doubles on a piece over 4,096 ulps long is refused now.
for q in -pq20 -pq21 -pq22 -pq30 -pq33.5 -pq34; do
  run 0 $q cluster.poly && counted_misses && verified_but_subsegments cluster.poly cluster.1
done
echo "ok"
