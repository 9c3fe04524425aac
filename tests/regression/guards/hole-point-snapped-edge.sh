#!/bin/sh
# A hole point one ulp inside a hole of area 9e-14 (issue 47, item 11): a vertex 2 ulps inside the
# hole's bottom edge is placed on it by the 4-ulp T-junction snapping, which bends the edge's chain
# through the hole point; the point was then "exactly on a segment", ignored, and the hole meshed.
# The point is tested against the input segment (strictly inside the hole), so the hole is carved.
# Independent facts: every vertex lies on the outer square or the hole's boundary, so a mesh of
# the square minus one hole has V + 2h - 2 = 9 triangles; no triangle's centroid lies in the hole.
# The same point as a region point (-A): the pentagon the rectangle became (its 5 vertices) is
# V - 2 = 3 triangles, and exactly the triangles inside the rectangle take the region's attribute.
#   hole-point-snapped-edge.sh DELTRI VERIFY
. "$(dirname "$0")/lib.sh"
cat >hole.poly <<'POLY'
9 2 0 0
1 0 0
2 1 0
3 1 1
4 0 1
5 0.5 0.5
6 0.5000009536743164 0.5
7 0.5000009536743164 0.5000000953674316
8 0.5 0.5000000953674316
9 0.5000004768371582 0.5000000000000002
8 0
1 1 2
2 2 3
3 3 4
4 4 1
5 5 6
6 6 7
7 7 8
8 8 5
1
1 0.5000002384185791 0.5000000000000001
POLY
# none_in_hole OUTBASE: no triangle of OUTBASE has its centroid inside the hole's rectangle.
none_in_hole() {
  awk 'FNR == 1 { f++ } f == 1 && FNR > 1 && !/^#/ && NF >= 3 { x[$1] = $2; y[$1] = $3 }
       f == 2 && FNR > 1 && !/^#/ && NF >= 4 {
         cx = (x[$2] + x[$3] + x[$4]) / 3; cy = (y[$2] + y[$3] + y[$4]) / 3
         if (cx > 0.5 && cx < 0.5000009536743164 && cy > 0.5 && cy < 0.5000000953674316) bad++ }
       END { exit bad > 0 }' "$1.node" "$1.ele" || fail "$1 has a triangle inside the hole"
}
run 0 -p hole.poly
grep -q "ignored" stderr.last && fail "the hole point was ignored"
[ "$(head -n 1 hole.1.ele | awk '{print $1}')" -eq 9 ] || fail "expected 9 triangles, got $(head -n 1 hole.1.ele)"
none_in_hole hole.1
verified hole.poly hole.1
ends_verified hole.poly hole.1 -pq30 hole.poly
grep -q "ignored" stderr.last && fail "the hole point was ignored at -pq30"
none_in_hole hole.1
sed -e 's/^1$/0\n1/' -e 's/^1 0.5000002384185791 0.5000000000000001$/1 0.5000002384185791 0.5000000000000001 7 0/' hole.poly >region.poly
run 0 -pA region.poly
grep -q "ignored" stderr.last && fail "the region point was ignored"
awk 'FNR == 1 { f++ } f == 1 && FNR > 1 && !/^#/ && NF >= 3 { x[$1] = $2; y[$1] = $3 }
     f == 2 && FNR > 1 && !/^#/ && NF >= 5 {
       cx = (x[$2] + x[$3] + x[$4]) / 3; cy = (y[$2] + y[$3] + y[$4]) / 3
       inside = cx > 0.5 && cx < 0.5000009536743164 && cy > 0.5 && cy < 0.5000000953674316
       if (inside != ($5 == 7)) bad++; n7 += ($5 == 7) }
     END { exit !(bad == 0 && n7 == 3) }' region.1.node region.1.ele ||
  fail "the region's attribute is not on exactly the 3 triangles inside the rectangle"
echo "ok"
