#!/bin/sh
# --size-field is estimated before refinement as -a is (issue 47, item 12): a field asking for an
# edge of 1e-7 over a unit square needs about 4 / (sqrt(3) h^2) = 2.3e14 triangles, far beyond any
# memory; it ran for 75 s and wrote 388 MB (the same request as -a was refused at once). It must
# be refused at once: exit 6, one line naming a triangle count between 1e14 and 1e15, no output.
# The same field at h = 0.01 (about 23,000 triangles) still meshes.
#   size-field-estimate.sh DELTRI VERIFY
. "$(dirname "$0")/lib.sh"
printf '4 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n0\n' >sq.poly
printf '2 3 0\n1 1 2 3\n2 1 3 4\n' >bg.ele
printf '4 2 1 0\n1 0 0 %s\n2 1 0 %s\n3 1 1 %s\n4 0 1 %s\n' 0.0000001 0.0000001 0.0000001 0.0000001 >bg.node
run 6 -pq30 --size-field=bg sq.poly
[ "$(wc -l <stderr.last)" -eq 1 ] || fail "not a one-line error"
n=$(sed -n 's/.*ask for about \([0-9.e+]*\) triangles.*/\1/p' stderr.last)
awk -v n="$n" 'BEGIN { exit !(n + 0 >= 1e14 && n + 0 <= 1e15) }' || fail "the estimate '$n' is not about 2.3e14"
[ ! -e sq.1.node ] && [ ! -e sq.1.ele ] || fail "outputs written"
printf '4 2 1 0\n1 0 0 %s\n2 1 0 %s\n3 1 1 %s\n4 0 1 %s\n' 0.01 0.01 0.01 0.01 >bg.node
ends_verified sq.poly sq.1 -pq30 --size-field=bg sq.poly
echo "ok"
