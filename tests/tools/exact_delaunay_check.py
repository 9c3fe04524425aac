#!/usr/bin/python3
"""An exact checker of deltri's output that shares nothing with deltri's predicates.

    exact_delaunay_check.py OUTBASE [--convex-hull INPUT.node]

Reads OUTBASE.node, OUTBASE.ele and, when present, OUTBASE.poly (its segments are the constrained
edges), converts every coordinate to the exact rational value of its double (fractions.Fraction of
the float parsed by Python, which rounds decimal text exactly like strtod), and checks:
  - every triangle strictly counter-clockwise;
  - every edge used by at most two triangles, in opposite directions (a manifold, consistently
    oriented);
  - the (constrained) Delaunay property: for every edge between two triangles that is not a
    segment, the far vertex of one is not strictly inside the circumcircle of the other;
  - with --convex-hull: every input vertex is a mesh vertex, the boundary edges are exactly the
    convex hull's edges, and the triangles' areas add up to the hull's area (so none overlap).
Prints one line per fault (at most 10) and exits 1 if any, else prints "ok" and exits 0.
"""
import sys
from fractions import Fraction


def numbers(path):
    rows = []
    with open(path) as f:
        for line in f:
            line = line.split('#', 1)[0].split()
            if line:
                rows.append(line)
    return rows


def read_nodes(path):
    rows = numbers(path)
    n = int(rows[0][0])
    pts = {}
    for r in rows[1:1 + n]:
        pts[int(r[0])] = (Fraction(float(r[1])), Fraction(float(r[2])))
    return pts


def orient(a, b, c):
    return (a[0] - c[0]) * (b[1] - c[1]) - (a[1] - c[1]) * (b[0] - c[0])


def incircle(a, b, c, d):
    adx, ady = a[0] - d[0], a[1] - d[1]
    bdx, bdy = b[0] - d[0], b[1] - d[1]
    cdx, cdy = c[0] - d[0], c[1] - d[1]
    return ((adx * adx + ady * ady) * (bdx * cdy - cdx * bdy) + (bdx * bdx + bdy * bdy) * (cdx * ady - adx * cdy)
            + (cdx * cdx + cdy * cdy) * (adx * bdy - bdx * ady))


def hull(points):
    pts = sorted(set(points))
    if len(pts) < 3:
        return pts
    lower, upper = [], []
    for p in pts:
        while len(lower) >= 2 and orient(lower[-2], lower[-1], p) <= 0:
            lower.pop()
        lower.append(p)
    for p in reversed(pts):
        while len(upper) >= 2 and orient(upper[-2], upper[-1], p) <= 0:
            upper.pop()
        upper.append(p)
    return lower[:-1] + upper[:-1]


def main(argv):
    base = argv[1]
    hull_input = argv[3] if len(argv) > 3 and argv[2] == '--convex-hull' else None
    pts = read_nodes(base + '.node')
    tris = [tuple(int(v) for v in r[1:4]) for r in numbers(base + '.ele')[1:]]
    segments = set()
    try:
        rows = numbers(base + '.poly')
        first = rows[0]
        offset = 1 + int(first[0])
        nseg = int(rows[offset][0])
        for r in rows[offset + 1:offset + 1 + nseg]:
            segments.add(frozenset((int(r[1]), int(r[2]))))
    except FileNotFoundError:
        pass
    faults = []
    edges = {}
    for t, (a, b, c) in enumerate(tris):
        if orient(pts[a], pts[b], pts[c]) <= 0:
            faults.append('triangle %d (%d %d %d) is not strictly counter-clockwise' % (t + 1, a, b, c))
        for (u, v, w) in ((a, b, c), (b, c, a), (c, a, b)):
            if (u, v) in edges:
                faults.append('edge %d-%d used twice in the same direction' % (u, v))
            edges[(u, v)] = w
    for (u, v), w in edges.items():
        other = edges.get((v, u))
        if other is None or u > v or frozenset((u, v)) in segments:
            continue
        if incircle(pts[u], pts[v], pts[w], pts[other]) > 0:
            faults.append('edge %d-%d is not locally Delaunay (vertex %d inside the circle of %d %d %d)'
                          % (u, v, other, u, v, w))
    if hull_input:
        inputs = list(read_nodes(hull_input).values())
        mesh_points = set(pts.values())
        missing = [p for p in inputs if p not in mesh_points]
        if missing:
            faults.append('%d input vertices are not mesh vertices' % len(missing))
        h = hull(inputs)
        hull_edges = {(h[i], h[(i + 1) % len(h)]) for i in range(len(h))}
        boundary = [(pts[u], pts[v]) for (u, v) in edges if (v, u) not in edges]
        # A boundary edge may be a piece of a hull edge split at collinear vertices.
        for (p, q) in boundary:
            if not any(orient(a, b, p) == 0 and orient(a, b, q) == 0 and orient(a, b, h[(h.index(b) + 1) % len(h)]) != 0
                       for (a, b) in hull_edges):
                faults.append('boundary edge not on the convex hull')
                break
        twice_area = sum(orient(pts[a], pts[b], pts[c]) for (a, b, c) in tris)
        hull_twice = sum(h[i][0] * h[(i + 1) % len(h)][1] - h[(i + 1) % len(h)][0] * h[i][1] for i in range(len(h)))
        if twice_area != hull_twice:
            faults.append('the triangles cover %s times the hull area' % (twice_area / hull_twice if hull_twice else 'n/a'))
    for line in faults[:10]:
        print(line)
    if faults:
        print('%d faults' % len(faults))
        return 1
    print('ok: %d triangles, %d edges' % (len(tris), len(edges)))
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
