#!/bin/sh
# -r on a mesh whose domain pinches at a vertex: two squares, markers 1 and 2, touching at (1, 1).
# The triangles around (1, 1) form two fans with outside between them, and the vertex index knows
# one; a segment leaving (1, 1) through the other fan was "outside every triangle ignored", and its
# pieces came out of -r with marker 1 (the unconstrained boundary's) instead of 2. Checked: no such
# warning, and every boundary edge of the refined mesh is a segment of the .poly with the marker of
# the square it bounds (by its midpoint, from the geometry alone).
#   refine-pinch-vertex.sh DELTRI
set -u
deltri=$1
work=$(mktemp -d) || exit 1
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
cat >pinch.poly <<'POLY'
7 2 0 0
1 0 0
2 1 0
3 1 1
4 0 1
5 2 1
6 2 2
7 1 2
8 1
1 1 2 1
2 2 3 1
3 3 4 1
4 4 1 1
5 3 5 2
6 5 6 2
7 6 7 2
8 7 3 2
0
POLY
"$deltri" -pq30Q pinch.poly || { echo "FAIL: -pq30 exit $?"; exit 1; }
"$deltri" -rq30a0.01 pinch.1.poly 2>stderr || { echo "FAIL: -rq30a0.01 exit $?"; cat stderr; exit 1; }
if grep -q "outside every triangle" stderr; then
  echo "FAIL: -r lost a segment:"; cat stderr; exit 1
fi
/usr/bin/python3 - <<'PY'
import sys
def rows(path):
    return [l.split('#')[0].split() for l in open(path) if l.split('#')[0].split()]
nodes = rows('pinch.2.node')
pts = {int(r[0]): (float(r[1]), float(r[2])) for r in nodes[1:]}
boundary = {}
for r in rows('pinch.2.ele')[1:]:
    t = [int(x) for x in r[1:4]]
    for i in range(3):
        e = frozenset((t[i], t[(i + 1) % 3]))
        boundary[e] = boundary.get(e, 0) + 1
boundary = {e for e, n in boundary.items() if n == 1}
poly = rows('pinch.2.poly')
count = int(poly[1][0])
segments = {frozenset((int(r[1]), int(r[2]))): int(r[3]) for r in poly[2:2 + count]}
bad = 0
for e in boundary:
    a, b = (pts[v] for v in e)
    mid = ((a[0] + b[0]) / 2, (a[1] + b[1]) / 2)
    want = 1 if mid[0] <= 1 and mid[1] <= 1 else 2
    got = segments.get(e)
    if got != want:
        bad += 1
        print(f"boundary edge {a}-{b}: marker {got}, wanted {want}")
print(f"{len(boundary)} boundary edges, {len(segments)} segments, {bad} wrong")
sys.exit(1 if bad or len(boundary) != len(segments) else 0)
PY
