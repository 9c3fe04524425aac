#!/bin/sh
# Refinement at any finite scale (issue 47, item 11): guitar.poly (its 4 holes included) with every
# coordinate multiplied by 2^232, 2^-200, 1e70 and 1e-60. Refinement was refused beyond +-2^200 and
# below 2^-150 (exit 1). Multiplying by a power of two is exact and commutes with every rounded
# operation while nothing overflows or underflows, so the mesh at 2^232 and at 2^-200 must be
# guitar's own mesh scaled, vertex for vertex and triangle for triangle; at 1e70 and 1e-60 (not
# exact) the mesh must pass deltri_mesh_verify with its 30 degrees; at 2^-900 it must be guitar's
# mesh scaled, as at 2^232. An input whose coordinates span
# more than the doubles' exponent range cannot be scaled exactly: a one-line error, no outputs.
#   refine-any-scale.sh DELTRI VERIFY
guitar=$(cd "$(dirname "$0")/../../../data" && pwd)/guitar.poly
. "$(dirname "$0")/lib.sh"
# scaled FACTOR OUT: guitar.poly with its vertex and hole coordinates multiplied by FACTOR.
scaled() {
  awk -v f="$1" 'BEGIN { part = 0 }
    /^[ \t]*(#|$)/ { next }
    left == 0 { part++; left = $1; print; if (part == 4) exit; next }
    { if (part != 2) { $2 = sprintf("%.17g", $2 * f); $3 = sprintf("%.17g", $3 * f) } print; left-- }' "$guitar" >"$2"
}
# coordinates OUTBASE FACTOR: the .node's vertices multiplied by FACTOR, then the .ele.
coordinates() {
  awk -v f="$2" 'NR > 1 && !/^#/ { printf "%s %.17g %.17g\n", $1, $2 * f, $3 * f }' "$1.node"
  cat "$1.ele"
}
scaled 1 guitar.poly
ends_verified guitar.poly guitar.1 -pq30 guitar.poly
coordinates guitar.1 1 >plain.txt
for e in 232 -200 -900; do
  awk -v e="$e" 'BEGIN { printf "%.17g\n", 2 ^ e }' >factor
  scaled "$(cat factor)" big.poly
  # (deltri_mesh_verify computes in doubles: at 2^-900 its products underflow; the comparison is exact)
  if [ "$e" -eq -900 ]; then run 0 -pq30 big.poly; else ends_verified big.poly big.1 -pq30 big.poly; fi
  coordinates big.1 "$(awk -v e="$e" 'BEGIN { printf "%.17g\n", 2 ^ -e }')" >big.txt
  cmp -s plain.txt big.txt || fail "the mesh of guitar.poly times 2^$e is not guitar's mesh times 2^$e"
done
for f in 1e70 1e-60; do
  scaled "$f" odd.poly
  run 0 -pq30 odd.poly && "$verify" --input odd.poly --mesh odd.1 --refined --min-angle 30 || fail "guitar times $f"
done
printf '4 2 0 0\n1 0 0\n2 1e70 0\n3 1e70 1e70\n4 1e-300 1e70\n4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n0\n' >span.poly
run 1 -pq30 span.poly
[ "$(wc -l <stderr.last)" -eq 1 ] && grep -q "^span.poly: .*cannot be scaled" stderr.last || fail "span.poly: not a one-line error"
[ ! -e span.1.node ] && [ ! -e span.1.ele ] || fail "span.poly: outputs written"
# Below 2^-970 new vertices would be subnormal numbers, too coarse for the input's features: the
# split points of -s and of refinement fell off their segments (-ps at 1e-310: chains off the
# segments, exit 0). Refused in one line, nothing written; -p alone still triangulates.
scaled 1e-310 sub.poly
for s in -pq30 -ps; do
  run 1 $s sub.poly
  [ "$(wc -l <stderr.last)" -eq 1 ] && grep -q "^sub.poly: .*subnormal" stderr.last || fail "sub.poly $s: not a one-line error"
  [ ! -e sub.1.node ] && [ ! -e sub.1.ele ] || fail "sub.poly $s: outputs written"
done
run 0 -p sub.poly
echo "ok"
