#!/bin/sh
# Two segments crossing at 1e-7 degrees in a 2 x 2 square (issue 47, item 7). -pq30 leaves the thin
# wedges at the crossing alone (their shortest edges join split points on equal shells of the two
# pieces from the crossing) and counts the triangles left there. Refining that output again
# (-r, or -p of its .poly) once ran away: every subsegment of the earlier run was a segment piece of
# its own, the wedges' triangles no longer had pieces sharing the crossing, and the wedges were
# refined down their whole length until the memory was gone. Each run of the chains below must
# end (CTest's timeout), exit 0, pass deltri_mesh_verify and count its misses.
#   tiny-crossing-r-chain.sh DELTRI VERIFY
. "$(dirname "$0")/lib.sh"
cat >cross.poly <<'POLY'
8 2 0 0
1 0 0
2 2 0
3 2 2
4 0 2
5 0.10000000000000001 1
6 1.8999999999999999 1
7 0.10000000000000001 0.99999999842920362
8 1.8999999999999999 1.0000000015707964
6 0
1 1 2
2 2 3
3 3 4
4 4 1
5 5 6
6 7 8
0
POLY
# -pq30, then -rpq30 twice
ends_counted cross.poly cross.1 -pq30 cross.poly
ends_counted cross.1.poly cross.2 -rpq30 cross.1
ends_counted cross.2.poly cross.3 -rpq30 cross.2
# -pq30, then -pq30 (and -pq20, -pq33) of its .poly without -r: the crossing is an input vertex
# there and the wedges' sides are chains of the first run's splits (item 7's rest; the chains that
# end at such a sharp junction are one piece each, refine/segment_pieces.h)
mkdir q && cp cross.poly q/ && cd q || exit 1
run 0 -pq30 cross.poly
ends_counted cross.1.poly cross.2 -pq30 cross.1.poly
ends_counted cross.2.poly cross.3 -pq30 cross.2.poly
ends_counted cross.1.poly cross.2 -pq20 cross.1.poly
ends_counted cross.1.poly cross.2 -pq33 cross.1.poly
cd .. || exit 1
# -p, then -rpq30 twice
mkdir p && cp cross.poly p/ && cd p || exit 1
run 0 -p cross.poly
ends_verified cross.1.poly cross.2 -rpq30 cross.1
ends_counted cross.2.poly cross.3 -rpq30 cross.2
cd .. || exit 1
# -pq30, then -rpq30a with an .area file, then -rpq30a0.01
mkdir a && cp cross.poly a/ && cd a || exit 1
run 0 -pq30 cross.poly
n=$(sed -n '1s/^ *\([0-9]*\).*/\1/p' cross.1.ele)
{ echo "$n"; i=1; while [ "$i" -le "$n" ]; do echo "$i 0.001"; i=$((i + 1)); done; } >cross.1.area
ends_counted cross.1.poly cross.2 -rpq30a cross.1
ends_counted cross.2.poly cross.3 -rpq30a0.01 cross.2
echo "ok"
