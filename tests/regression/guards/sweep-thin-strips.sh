#!/bin/sh
# Two runs of the random sweep (tests/sweep/random_sweep.py, seed 47, runs 1585 and 956) that ran
# past its 60 s (issue 47): segments meeting at about 1e-15 radians, their far ends a few ulps
# apart (0.75 beside 0.750000000000001; 500000 beside 500000.000000001), so a strip between them
# a few ulps wide and a few tenths of the domain long. -D (an empty diametral circle for every
# subsegment) and quality refinement split both sides down to pieces as short as the strip is
# wide, about 1e15 splits. A subsegment over 4,096 ulps long is no longer split for quality or
# -D when a triangle on it is narrower than 16 ulps (BottomScale::in_strip_below_an_ulp, refine/bottom_scale.h); each run
# must end (CTest's timeout), exit 0 with the unmet -D subsegments counted, and pass
# deltri_mesh_verify.
#   sweep-thin-strips.sh DELTRI VERIFY
. "$(dirname "$0")/lib.sh"
cat >r1585.poly <<'POLY'
18 2 0 0
1 0.500000000000001 0.125
2 0.375 0.375
3 0.750000000000001 0.625
4 0.0 0.125
5 0.625 0.25
6 0.0 0.75
7 0.75 0.625
8 0.875 0.0
9 0.375 0.25
10 0.875 0.125
11 0.500000000000001 0.75
12 0.75 0.625
13 0.0 0.25
14 0.625 1.0
15 -0.25 -0.25
16 1.25 -0.25
17 1.25 1.25
18 -0.25 1.25
18 0
1 6 12
2 2 6
3 3 7
4 7 11
5 2 8
6 2 4
7 11 5
8 5 7
9 9 5
10 5 8
11 12 8
12 4 5
13 3 8
14 6 8
15 15 16
16 16 17
17 17 18
18 18 15
1
1 0.6875 0.1875
POLY
cat >r956.poly <<'POLY'
18 2 0 0
1 375000.0 0.0
2 1000000.0 125000.0
3 625000.0 0.0
4 500000.000000001 750000.0
5 0.0 125000.0
6 250000.0 500000.0
7 250000.0 375000.0
8 1000000.0 750000.0
9 500000.0000000001 1000000.0
10 1000000.0 500000.0
11 4.940656e-318 875000.0
12 1000000.0 250000.0
13 500000.0 250000.0
14 875000.0 500000.0
15 -250000.0 -250000.0
16 1250000.0 -250000.0
17 1250000.0 1250000.0
18 -250000.0 1250000.0
13 0
1 10 5
2 10 13
3 14 6
4 4 9
5 11 8
6 5 2
7 14 7
8 3 11
9 13 9
10 15 16
11 16 17
12 17 18
13 18 15
0
POLY
ends_verified r1585.poly r1585.1 -pD r1585.poly
grep -q "subsegments\{0,1\} \(is\|are\) not Delaunay" stderr.last || fail "-pD: no count of the subsegments left not Delaunay"
ends_verified r956.poly r956.1 -pq33D --range-restricted r956.poly
grep -q "subsegments\{0,1\} \(is\|are\) not Delaunay" stderr.last || fail "-pq33D: no count of the subsegments left not Delaunay"
counted_misses
echo "ok"
