#!/usr/bin/env python3
"""With -Y / -YY, no output angle may lie below the floor the fixed boundary certainly allows.

    kept_boundary_bound.py DELTRI INPUT.poly SWITCHES [--at-least=DEGREES]
                                                      (SWITCHES such as -pYYq, -pYYq33, -pYq30)

The floor is min(q, m), where q is the -q angle (20 when bare) and m the smallest angle of the
input's constrained Delaunay triangulation, read from `DELTRI -p` (triangulation only, no
refinement). That triangulation keeps every segment whole and adds no vertex, so it is a mesh the
fixed boundary allows; and as a constrained Delaunay triangulation maximises the smallest angle
over all triangulations of its vertices that keep its segments, m is a fact of the input geometry,
not of deltri: the script checks that the -p output is constrained Delaunay (every edge that is not
a segment passes the empty-circle test, in exact rational arithmetic), so that a wrong -p
triangulation cannot lower the floor. Where no subsegment may be split (-YY, or a single -Y on an
input whose segments all lie on the boundary) deltri proves the floor with a size bound (-a, -u)
and half of it, min(q, m) / 2, without one: no insertion makes a triangle below it that is worse
than every triangle it replaces (docs/refinement.md, "-Y, -YY"). Without a size bound the whole
floor is what every corpus run reaches (measured, not proved: an insertion may dip below it for a
triangle that a later point splits, as Triangle 1.6 does), and the cases registered in
tests/CMakeLists.txt must reach it too: the script fails below either, and says which. With a single -Y and an interior segment the script refuses the case, as
no such floor holds there. Also checks that every segment that the switches keep whole (all with
-YY, the boundary ones with -Y) is still an edge of the refined mesh. Angles are computed here
from the written .node/.ele in doubles; nothing deltri reports about quality is used.

With --at-least=DEGREES the smallest angle must also be at least that: the figure another program
(Triangle 1.6) reaches on the same input and switches, an independent fact about what the fixed
boundary allows. Such a case may have interior segments under a single -Y: then only the kept
segments and that figure are checked, as no floor holds there.

Also fails when a run fails. Exit 0 when the check passes, 1 otherwise. On main before
issue 16 (9e54440) debug2.poly -pYYq33 failed: 0.0111 degrees against a floor of 0.0180 (Triangle
1.6: 0.0123), and water-huge.poly -pYYq33: 0.0307 against 0.1282. With the floor rule left out
for a single -Y (2df5ef3), touching-holes6.poly -pYq failed: see tests/CMakeLists.txt.
"""
import collections, math, os, re, shutil, subprocess, sys, tempfile
from fractions import Fraction


def rows(path):
    out = []
    with open(path) as f:
        for line in f:
            r = line.split('#')[0].split()
            if r: out.append(r)
    return out


def angle_at(w, a, b):
    ux, uy = a[0] - w[0], a[1] - w[1]
    vx, vy = b[0] - w[0], b[1] - w[1]
    return math.degrees(math.atan2(abs(ux * vy - uy * vx), ux * vx + uy * vy))


def run(deltri, inp, switches, d):
    for f in os.listdir(d): os.remove(os.path.join(d, f))
    shutil.copy(inp, d)
    base = os.path.basename(inp)[:-5]
    r = subprocess.run([deltri, switches + 'Q', base + '.poly'], cwd=d, capture_output=True, text=True, timeout=600)
    if r.returncode != 0:
        raise SystemExit(f'FAIL: {base} {switches}: exit {r.returncode}: {r.stderr.strip()}')
    nr = rows(os.path.join(d, base + '.1.node'))
    pts = {int(x[0]): (float(x[1]), float(x[2])) for x in nr[1:1 + int(nr[0][0])]}
    er = rows(os.path.join(d, base + '.1.ele'))
    tris = [tuple(int(v) for v in x[1:4]) for x in er[1:1 + int(er[0][0])]]
    pr = rows(os.path.join(d, base + '.1.poly'))
    segs = [(int(x[1]), int(x[2])) for x in pr[2:2 + int(pr[1][0])]]
    return pts, tris, segs


def edge_triangles(tris):
    """Each undirected edge with the vertices opposite it."""
    opposite = collections.defaultdict(list)
    for a, b, c in tris:
        for u, v, w in ((a, b, c), (b, c, a), (c, a, b)):
            opposite[frozenset((u, v))].append(w)
    return opposite


def incircle(a, b, c, d):
    """> 0 when d lies strictly inside the circle through the counter-clockwise a, b, c; exact."""
    a, b, c, d = ([Fraction(x) for x in p] for p in (a, b, c, d))
    rows_ = [(p[0] - d[0], p[1] - d[1]) for p in (a, b, c)]
    m = [(x, y, x * x + y * y) for x, y in rows_]
    return (m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
            + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]))


def check_constrained_delaunay(pts, tris, segs):
    """None if every edge that is not a segment is locally Delaunay, else a message."""
    seg_set = {frozenset(s) for s in segs}
    opposite = edge_triangles(tris)
    for a, b, c in tris:
        for u, v, w in ((a, b, c), (b, c, a), (c, a, b)):
            e = frozenset((u, v))
            if e in seg_set: continue
            for x in opposite[e]:
                if x != w and incircle(pts[u], pts[v], pts[w], pts[x]) > 0:
                    return f'edge {u}-{v} of the -p triangulation is not Delaunay (vertex {x} in the circle)'
    return None


def smallest_angle(pts, tris):
    smallest, where = 180.0, None
    for t in tris:
        a, b, c = pts[t[0]], pts[t[1]], pts[t[2]]
        m = min(angle_at(a, b, c), angle_at(b, c, a), angle_at(c, a, b))
        if m < smallest: smallest, where = m, t
    return smallest, where


def main():
    deltri, inp, switches = sys.argv[1:4]
    at_least = next((float(a.split('=', 1)[1]) for a in sys.argv[4:] if a.startswith('--at-least=')), None)
    q = re.search(r'q([0-9.]*)', switches)
    theta = float(q.group(1)) if q and q.group(1) else 20.0
    d = tempfile.mkdtemp()
    try:
        pts0, tris0, segs0 = run(deltri, inp, '-p', d)
        pts, tris, _ = run(deltri, inp, switches, d)
    finally:
        shutil.rmtree(d)
    name = os.path.basename(inp)
    problem = check_constrained_delaunay(pts0, tris0, segs0)
    if problem: raise SystemExit(f'FAIL: {name} -p: {problem}')
    sides = edge_triangles(tris0)
    interior = [s for s in segs0 if len(sides[frozenset(s)]) == 2]
    all_kept = re.search(r'YY', switches) is not None
    floor_holds = all_kept or not interior
    if not floor_holds and at_least is None:
        raise SystemExit(f'FAIL: {name} {switches}: {len(interior)} interior segments; a single -Y keeps no floor there')
    # Kept segments are those with one triangle (-Y) or all (-YY); -p's vertices keep their numbers.
    kept = segs0 if all_kept else [s for s in segs0 if len(sides[frozenset(s)]) == 1]
    edges = edge_triangles(tris)
    split = [s for s in kept if frozenset(s) not in edges]
    if split: raise SystemExit(f'FAIL: {name} {switches}: kept segment {split[0]} is not an edge of the mesh')
    m, _ = smallest_angle(pts0, tris0)
    floor = min(theta, m) if floor_holds else 0.0
    smallest, where = smallest_angle(pts, tris)
    sized = re.search(r'[au]', switches) is not None
    proven_floor = floor if sized else 0.5 * floor
    proven = smallest >= proven_floor * (1 - 1e-9)
    reached = at_least is None or smallest >= at_least
    ok = proven and smallest >= floor * (1 - 1e-9) and reached
    verdict = ('ok' if ok else 'FAIL (below the proven half floor)' if not proven
               else 'FAIL (below the other program)' if not reached else 'FAIL')
    other = '' if at_least is None else f', the other program {at_least:g}'
    floors = (f'floor {floor:.4f} = min(q {theta:g}, initial triangulation {m:.4f}), proven {proven_floor:.4f}'
              if floor_holds else 'no floor (interior segments under a single -Y)')
    print(f'{verdict}: {name} {switches}: smallest angle {smallest:.4f} (triangle {where}), {floors}{other}; '
          f'{len(tris)} triangles')
    return 0 if ok else 1


sys.exit(main())
