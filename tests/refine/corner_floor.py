"""No triangle below the input angle of the small corner it sits at (issue 42), in 2-D at -pq30.

Wedges of 7.083, 15 and 25 degrees at the origin, sides 10 long, with one free input point on the
bisector at 0.1 or 1 from the apex, so that refinement puts concentric shells into the corner.
Shells a factor 2 apart leave, beyond the corner triangle, a triangle joining the shell points at r
on both sides to the one at 2r on one side, whose angle there is atan(sin t / (2 - cos t)) < t
(6.977 degrees at t = 7.083). Checked from the written .node/.ele with exact rational arithmetic
on the printed coordinates, none of deltri's figures:
- every angle of every triangle, except the angles at the apex itself (which lie between the two
  segments and sum to the input angle), is at least the apex angle t, computed exactly from the
  input vertices as written (cosines compared through their squares and signs);
- every triangle below 30 degrees has a vertex on one of the apex's two segments (the shells lie
  on them): nothing else forces a triangle under the bound;
- the mesh is a triangulation of the wedge: the areas sum to the wedge's, exactly.
usage: corner_floor.py DELTRI
"""
import math
import os
import subprocess
import sys
import tempfile
from fractions import Fraction


def table(path):
    rows = [line.split('#')[0].split() for line in open(path)]
    return [r for r in rows if r]


def cos_key(o, u, v):
    """(dot, squared norms product) of the angle at o between u and v: cos = dot / sqrt(norms)."""
    ux, uy, vx, vy = u[0] - o[0], u[1] - o[1], v[0] - o[0], v[1] - o[1]
    return ux * vx + uy * vy, (ux * ux + uy * uy) * (vx * vx + vy * vy)


def at_least(angle, bound):
    """Exactly: the angle of cos_key `angle` is at least that of `bound` (cos not greater)."""
    (d1, n1), (d2, n2) = angle, bound
    if (d1 < 0) != (d2 < 0):
        return d1 < 0
    if d1 >= 0:
        return d1 * d1 * n2 <= d2 * d2 * n1
    return d1 * d1 * n2 >= d2 * d2 * n1


def below_degrees(angle, degrees):
    d, n = angle
    c = math.cos(math.radians(degrees))
    return d / math.sqrt(n) > c + 1e-12


def on_segment(p, a, b):
    cross = (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0])
    length2 = (b[0] - a[0]) ** 2 + (b[1] - a[1]) ** 2
    return cross * cross <= Fraction(1, 10**24) * length2 * length2  # printed points are rounded


def check(deltri, work, degrees, inside):
    t = math.radians(degrees)
    pts = [(0.0, 0.0), (10.0, 0.0), (10 * math.cos(t), 10 * math.sin(t)),
           (inside * math.cos(t / 2), inside * math.sin(t / 2))]
    name = f'wedge{round(degrees)}_{str(inside).replace(".", "_")}'
    with open(f'{work}/{name}.poly', 'w') as f:
        f.write('4 2 0 0\n' + ''.join(f'{i + 1} {x!r} {y!r}\n' for i, (x, y) in enumerate(pts)))
        f.write('3 0\n1 1 2\n2 2 3\n3 3 1\n0\n')
    run = subprocess.run([deltri, '-pq30', f'{name}.poly'], cwd=work, capture_output=True, text=True, timeout=300)
    if run.returncode != 0:
        return [f'{name}: deltri exited {run.returncode}: {run.stderr.strip()}']
    inp = table(f'{work}/{name}.poly')
    j, s1, s2 = [tuple(Fraction(x) for x in inp[i][1:3]) for i in (1, 2, 3)]
    corner = cos_key(j, s1, s2)
    rows = table(f'{work}/{name}.1.node')
    p = {int(r[0]): (Fraction(r[1]), Fraction(r[2])) for r in rows[1:1 + int(rows[0][0])]}
    rows = table(f'{work}/{name}.1.ele')
    tris = [[p[int(x)] for x in r[1:4]] for r in rows[1:1 + int(rows[0][0])]]
    faults, area, smallest = [], Fraction(0), 180.0
    for tri in tris:
        a, b, c = tri
        area += ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])) / 2
        keys = [cos_key(tri[i], tri[(i + 1) % 3], tri[(i + 2) % 3]) for i in range(3)]
        for i, key in enumerate(keys):
            if tri[i] != j and not at_least(key, corner):
                faults.append(f'{name}: an angle of {math.degrees(math.acos(key[0] / math.sqrt(key[1]))):.4f} '
                              f'below the {degrees}-degree corner at {[tuple(map(float, v)) for v in tri]}')
            if tri[i] != j:
                smallest = min(smallest, math.degrees(math.acos(min(1.0, key[0] / math.sqrt(key[1])))))
        if any(below_degrees(k, 30.0) for k in keys) and not any(
                on_segment(v, j, s1) or on_segment(v, j, s2) for v in tri):
            faults.append(f'{name}: a triangle below 30 degrees away from the corner at '
                          f'{[tuple(map(float, v)) for v in tri]}')
    wedge = ((s1[0] - j[0]) * (s2[1] - j[1]) - (s1[1] - j[1]) * (s2[0] - j[0])) / 2
    if abs(area - wedge) > Fraction(1, 10**9) * wedge:
        faults.append(f'{name}: triangles of area {float(area)} against the wedge\'s {float(wedge)}')
    print(f'{name}: {len(tris)} triangles, smallest angle off the apex {smallest:.4f} (corner {degrees})')
    return faults


def main():
    deltri = os.path.abspath(sys.argv[1])
    faults = []
    with tempfile.TemporaryDirectory() as work:
        for degrees in (7.083, 15.0, 25.0):
            for inside in (0.1, 1.0):
                faults += check(deltri, work, degrees, inside)
    if faults:
        sys.exit('\n'.join(faults))


main()
