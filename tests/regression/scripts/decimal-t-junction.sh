#!/bin/sh
# Issue 17 item 8: a segment endpoint written in decimal on another segment (here (0.1, 0.3) on
# the segment from (0, 0) to (0.3, 0.9)) is a rounding away from it in binary (1.4e-17 off the
# line). By default such a vertex (within 4 ulps) splits the segment, with a warning that counts
# the snaps, so no sliver of about 1e-15 degrees is left beside it; --exact-input keeps the
# coordinates' exact geometry (and the sliver).
#   decimal-t-junction.sh DELTRI
set -u
deltri=$1
work=$(mktemp -d) || exit 1
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
fail=0
printf '5 2 0 1\n1 0 0 0\n2 0.3 0.9 0\n3 0.1 0.3 0\n4 0.6 0.2 0\n5 0.6 0.9 0\n5 1\n1 1 2 1\n2 3 4 1\n3 1 4 1\n4 4 5 1\n5 5 2 1\n0\n' > tee.poly
# The smallest angle of the mesh, in degrees, from the output files.
min_angle() {
  /usr/bin/python3 - "$1" <<'PY'
import math, sys
base = sys.argv[1]
rows = [l.split() for l in open(base + '.node') if l.split() and not l.startswith('#')]
pts = {int(r[0]): (float(r[1]), float(r[2])) for r in rows[1:]}
worst = 180.0
for l in list(open(base + '.ele'))[1:]:
    r = l.split()
    if not r or r[0].startswith('#'):
        continue
    c = [pts[int(v)] for v in r[1:4]]
    for i in range(3):
        a, b, d = c[i], c[(i + 1) % 3], c[(i + 2) % 3]
        u = (b[0] - a[0], b[1] - a[1]); v = (d[0] - a[0], d[1] - a[1])
        worst = min(worst, math.degrees(abs(math.atan2(u[0] * v[1] - u[1] * v[0], u[0] * v[0] + u[1] * v[1]))))
print('%.3g' % worst)
PY
}
"$deltri" -pQ tee.poly 2>stderr
angle=$(min_angle tee.1)
echo "default: smallest angle $angle degrees; $(cat stderr)"
grep -q "1 vertex within 4 ulps of a segment placed on it" stderr || { echo "FAIL: no snap warning"; fail=1; }
/usr/bin/python3 -c "import sys; sys.exit(0 if float('$angle') > 1 else 1)" || { echo "FAIL: a sliver is left"; fail=1; }
"$deltri" -pQ --exact-input tee.poly 2>stderr
angle=$(min_angle tee.1)
echo "--exact-input: smallest angle $angle degrees; $(cat stderr)"
[ ! -s stderr ] || { echo "FAIL: --exact-input should not snap"; fail=1; }
/usr/bin/python3 -c "import sys; sys.exit(0 if float('$angle') < 1e-6 else 1)" || { echo "FAIL: --exact-input should keep the exact geometry"; fail=1; }
[ $fail -eq 0 ] && echo ok
exit $fail
