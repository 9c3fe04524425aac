#!/bin/sh
# --corner-lopping on a segment that overlaps a collinear chain (issue 47, item 8): a diamond with
# the chain (0,0)-(1,0)-(2,0)-(3,0) and the segment (0,0)-(3,0) over it. The overlapping segments
# leave (0,0) and (3,0) in one direction; their sector of width 0 was taken for a full turn, the
# corners were lopped with a shield vertex on each of the two segments (the same point twice), the
# run warned of duplicate vertices and repeated segments the input does not have, and the shield at
# (3,0), rounded 4e-17 off the axis, left a strip narrower than an ulp between the segment and
# the chain, refined without end (1.35 GB in 120 s). Such corners are not lopped: the run repairs
# the input as plain -pq20 does, with the same warnings, and ends (CTest's timeout).
#   lopping-collinear-chain.sh DELTRI VERIFY
. "$(dirname "$0")/lib.sh"
cat >diamond.poly <<'POLY'
6 2 0 0
1 0 0
2 1.5 1
3 3 0
4 1.5 -1
5 1 0
6 2 0
8 0
1 1 2
2 2 3
3 3 4
4 4 1
5 1 5
6 5 6
7 6 3
8 1 3
0
POLY
ends_verified diamond.poly diamond.1 -pq20 diamond.poly
cp stderr.last plain.stderr
for q in -pq20 -pq30; do
  ends_verified diamond.poly diamond.1 $q --corner-lopping diamond.poly
  ! grep -Eq "duplicate|repeated" stderr.last || fail "$q --corner-lopping warns of duplicates the input does not have"
  grep -q "2 segment splits where segments pass exactly through vertices" stderr.last &&
    grep -q "1 collinear overlap between segments merged" stderr.last || fail "$q --corner-lopping: not the repairs made"
  [ "$q" != -pq20 ] || cmp -s plain.stderr stderr.last || fail "-pq20 --corner-lopping warns otherwise than -pq20"
done
echo "ok"
