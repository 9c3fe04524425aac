#!/usr/bin/env python3
"""Spokes to the boundary: the unit square with 360 segments from its centre (0.5, 0.5) to the
points where the rays at 0, 1, ..., 359 degrees from the centre meet its boundary.

    spokes.py DELTRI VERIFY WORKDIR BOUND

The input has 360 input angles of 1 degree at the centre and no other angle under 44 degrees (a
spoke meets a side at 45 degrees or more, the sides meet at 90). Every triangle lies between two
neighbouring spokes; the angle forces a triangle below the bound only where the triangle is inside
the angle in the sense of Shewchuk 2001, Sec. 6: it has a corner at the apex, or its shortest edge
runs across the wedge from one spoke to the other (the concentric shells end splitting there, and
the Terminator leaves such a triangle as it is). Nothing forces any other triangle below the bound.
Triangle 1.6 leaves none other either (at -pq20 4,404 triangles under 20 degrees, at -pq30 7,078
under 30, every one with its shortest edge across a wedge, worst 9.9 and 16.5 degrees). So deltri
-pqBOUND must give a mesh in which

  * every triangle without a corner at the centre and without its shortest edge from one spoke to
    the neighbouring one has its smallest angle at least BOUND;
  * every triangle with a corner at the centre has its other two corners in the closed wedge
    between two neighbouring spokes (to within 1e-9 degrees: split points are rounded) and an
    angle of at most 1 degree there;
  * no angle is below Theorem 12's floor for the Terminator with diametral lenses (Sec. 6.4):
    arcsin((sqrt 3 / 2) sin(phi / 2)) with phi = 1 degree, 0.433 degrees;
  * the triangles cover the square (their areas, exact rationals of the doubles, add up to 1), and
    deltri_mesh_verify (VERIFY) passes the mesh with --refined --min-angle BOUND;

and deltri must exit 0 without warning of missed bounds (every miss is forced). Angles are computed
here in double precision with atan2 and a slack of 1e-9 degrees, independently of deltri's quality
account. The boundary points are exact: the coordinate the ray meets is exactly 0 or 1, the corners
are the square's own; the other coordinate is 0.5 +- 0.5 tan of the angle from the nearer axis,
written with %.17g.
"""
import math, os, shutil, subprocess, sys
from fractions import Fraction

deltri, verify, work, bound = sys.argv[1], sys.argv[2], sys.argv[3], float(sys.argv[4])
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
CENTRE = (0.5, 0.5)
CORNERS = {45: (1.0, 1.0), 135: (0.0, 1.0), 225: (0.0, 0.0), 315: (1.0, 0.0)}


def boundary_point(k):
    if k in CORNERS:
        return CORNERS[k]
    a = math.radians(k)
    c, s = math.cos(a), math.sin(a)
    if abs(c) > abs(s):  # meets a vertical side
        return (1.0 if c > 0 else 0.0, 0.5 + 0.5 * s / abs(c))
    return (0.5 + 0.5 * c / abs(s), 1.0 if s > 0 else 0.0)


ends = [boundary_point(k) for k in range(360)]
points = [CENTRE] + ends
lines = [f"{len(points)} 2 0 0"]
lines += [f"{i + 1} {x:.17g} {y:.17g}" for i, (x, y) in enumerate(points)]
lines.append(f"{2 * 360} 0")
for k in range(360):
    lines.append(f"{k + 1} 1 {k + 2}")  # the spoke at k degrees
for k in range(360):
    lines.append(f"{361 + k} {k + 2} {(k + 1) % 360 + 2}")  # the side from k to k + 1 degrees
lines.append("0")
with open(os.path.join(work, "spokes.poly"), "w") as f:
    f.write("\n".join(lines) + "\n")
# The written points, read back as deltri reads them.
ends = [(float(f"{x:.17g}"), float(f"{y:.17g}")) for x, y in ends]

switches = f"-pq{sys.argv[4]}"
r = subprocess.run([deltri, switches, "spokes.poly"], cwd=work, capture_output=True, text=True, timeout=600)
failures = []
if r.returncode != 0:
    failures.append(f"deltri {switches} exited {r.returncode}")
if "miss the requested bounds" in r.stderr:
    failures.append(f"deltri warned of missed bounds: {r.stderr.strip()}")


def rows(path):
    with open(os.path.join(work, path)) as f:
        for line in f:
            w = line.split("#")[0].split()
            if w:
                yield w


node_rows = rows("spokes.1.node")
n = int(next(node_rows)[0])
pts = {}
for _ in range(n):
    w = next(node_rows)
    pts[int(w[0])] = (float(w[1]), float(w[2]))
ele_rows = rows("spokes.1.ele")
count = int(next(ele_rows)[0])
triangles = [[pts[int(v)] for v in next(ele_rows)[1:4]] for _ in range(count)]


def angle_at(o, p, q):
    ux, uy, vx, vy = p[0] - o[0], p[1] - o[1], q[0] - o[0], q[1] - o[1]
    return math.degrees(math.atan2(abs(ux * vy - uy * vx), ux * vx + uy * vy))


def orient(a, b, c):  # exact, on the doubles' rational values
    a, b, c = [(Fraction(p[0]), Fraction(p[1])) for p in (a, b, c)]
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])


def turn(a, b, c):
    """The angle from a->b to a->c in degrees, counter-clockwise positive."""
    ux, uy, vx, vy = b[0] - a[0], b[1] - a[1], c[0] - a[0], c[1] - a[1]
    return math.degrees(math.atan2(ux * vy - uy * vx, ux * vx + uy * vy))


def in_a_wedge(p, q):
    """p and q lie in the closed wedge between the spokes at some k and k + 1 degrees (split
    points on a spoke are rounded, so to within 1e-9 degrees)."""
    near = int(math.floor(math.degrees(math.atan2(p[1] - 0.5, p[0] - 0.5)))) % 360
    for k in ((near - 1) % 360, near, (near + 1) % 360):  # the wedge found by angle, confirmed exactly
        lo, hi = ends[k], ends[(k + 1) % 360]
        if all(turn(CENTRE, lo, z) >= -1e-9 and turn(CENTRE, z, hi) >= -1e-9 for z in (p, q)):
            return True
    return False


def spoke_of(p):
    """The k of the spoke at k degrees that p lies on (within 1e-9 degrees), or None; the ends on
    the boundary count as the boundary's."""
    if p[0] in (0.0, 1.0) or p[1] in (0.0, 1.0):
        return None
    k = round(math.degrees(math.atan2(p[1] - 0.5, p[0] - 0.5))) % 360
    return k if abs(turn(CENTRE, ends[k], p)) <= 1e-9 else None


def across_a_wedge(tri):
    """The triangle's shortest edge joins two neighbouring spokes."""
    p, q = min(((tri[i], tri[(i + 1) % 3]) for i in range(3)), key=lambda e: math.dist(*e))
    a, b = spoke_of(p), spoke_of(q)
    return a is not None and b is not None and (a - b) % 360 in (1, 359)


FLOOR = math.degrees(math.asin(math.sqrt(3) / 2 * math.sin(math.radians(0.5))))
total = Fraction(0)
worst_elsewhere, bad_elsewhere, at_centre, across, worst = 180.0, 0, 0, 0, 180.0
for tri in triangles:
    a, b, c = tri
    total += abs(orient(a, b, c)) / 2
    smallest = min(angle_at(a, b, c), angle_at(b, c, a), angle_at(c, a, b))
    worst = min(worst, smallest)
    if CENTRE in tri:
        at_centre += 1
        i = tri.index(CENTRE)
        p, q = tri[(i + 1) % 3], tri[(i + 2) % 3]
        if not in_a_wedge(p, q):
            failures.append(f"triangle {tri} at the centre is not inside a 1-degree angle")
        elif angle_at(CENTRE, p, q) > 1.0 + 1e-9:
            failures.append(f"triangle {tri} has {angle_at(CENTRE, p, q)} degrees at the centre")
        continue
    if smallest < bound - 1e-9 and across_a_wedge(tri):
        across += 1
        continue
    worst_elsewhere = min(worst_elsewhere, smallest)
    if smallest < bound - 1e-9:
        bad_elsewhere += 1
        if bad_elsewhere <= 5:
            failures.append(f"triangle {tri} outside the 1-degree angles has a {smallest:.6g} degree angle")
if bad_elsewhere > 5:
    failures.append(f"... {bad_elsewhere} triangles outside the 1-degree angles below {bound} degrees in all")
if worst < FLOOR - 1e-9:
    failures.append(f"an angle of {worst:.6g} degrees, below Theorem 12's floor of {FLOOR:.4f}")
if total != 1:
    failures.append(f"the triangles' areas add up to {float(total)!r}, not 1")
v = subprocess.run([verify, "--input", "spokes.poly", "--mesh", "spokes.1", "--refined", "--min-angle", sys.argv[4]],
                   cwd=work, capture_output=True, text=True, timeout=600)
if v.returncode != 0:
    failures.append(f"deltri_mesh_verify: {v.stdout.strip()} {v.stderr.strip()}")
if failures:
    print("\n".join("FAIL: " + f for f in failures))
    sys.exit(1)
print(f"deltri {switches} spokes.poly: {count} triangles, {at_centre} at the centre and {across} across a wedge under "
      f"{bound} (smallest angle {worst:.4f} >= {FLOOR:.4f}), the others' smallest angle {worst_elsewhere:.4f} >= {bound}")
