#!/bin/sh
# Segments that cross where every coordinate is subnormal (issue 47, the random sweep's largest
# class): a square of side 4e-320 with its two diagonals. The crossing point (2e-320, 2e-320) is
# a multiple of 2^-1074 here, but in general the crossing is rounded to that grid, off both
# segments, and plain -p exited 0 with segments that were no chains of mesh edges. It is refused
# in one line, as refinement is refused below 2^-970, nothing written; without the crossing the
# square still meshes, and the same input at scale 1 meshes with its crossing.
#   subnormal-crossing.sh DELTRI VERIFY
. "$(dirname "$0")/lib.sh"
square() {  # square SIDE SEGMENTS...: the square of that side, its four sides and the given segments
  s=$1
  shift
  printf '4 2 0 0\n1 0 0\n2 %s 0\n3 %s %s\n4 0 %s\n%d 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n' "$s" "$s" "$s" "$s" $((4 + $#))
  k=5
  for seg in "$@"; do
    echo "$k $seg"
    k=$((k + 1))
  done
  echo 0
}
square 4e-320 "1 3" "2 4" >cross.poly
for sw in -p -pc; do
  run 1 $sw cross.poly
  [ "$(wc -l <stderr.last)" -eq 1 ] || fail "$sw: not a one-line error"
  grep -q "crossing of segments where every vertex coordinate is below" stderr.last || fail "$sw: the error does not name the crossing"
  [ ! -e cross.1.node ] && [ ! -e cross.1.ele ] || fail "$sw: outputs written"
done
run 1 -pq30 cross.poly  # refinement: refused below 2^-970 already, before the crossing
square 4e-320 "1 3" >one.poly
ends_verified one.poly one.1 -p one.poly
square 4 "1 3" "2 4" >big.poly
ends_verified big.poly big.1 -p big.poly
echo "ok"
