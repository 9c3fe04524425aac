"""Divide and conquer (default), -l, -i and -F give the same triangles on inputs full of cocircular
ties, each run with the checker (-C, exit status 0); and those triangles are, edge by edge, the
Delaunay triangulation of the symbolically perturbed points that deltri's tie rule defines
(docs/architecture.md, "Cocircular ties"), judged here with exact rationals, independently of
deltri: each point's lift x^2 + y^2 lowered by eps^rank (rank in lexicographic (x, y) order).
That triangulation is unique, so agreeing with it edge by edge pins every diagonal.

    one_triangulation.py DELTRI WORK_DIR
"""
import math
import os
import random
import shutil
import subprocess
import sys
from fractions import Fraction


def grid(w, h, step, seed):
    pts = [(i * step, j * step) for i in range(w) for j in range(h)]
    random.Random(seed).shuffle(pts)
    return pts


def polygon(n, radius, centre, with_centre):
    pts = [(centre[0] + radius * math.cos(2 * math.pi * i / n), centre[1] + radius * math.sin(2 * math.pi * i / n))
           for i in range(n)]
    return pts + [centre] if with_centre else pts


def lattice_circles(radii, centre):
    pts = [(centre[0] + x, centre[1] + y) for r in radii for x in range(-r, r + 1) for y in range(-r, r + 1)
           if x * x + y * y == r * r]
    return pts + [centre]


def lattice_subset(w, h, keep, seed):
    rng = random.Random(seed)
    pts = [(i * 0.5, j * 0.5) for i in range(w) for j in range(h) if rng.random() < keep]
    pts += pts[::13]  # duplicates
    rng.shuffle(pts)
    return pts


def uniform(n, seed):
    rng = random.Random(seed)
    return [(rng.random(), rng.random()) for _ in range(n)]


SETS = {
    "grid": grid(23, 17, 0.25, 1),
    "far_grid": [(1e9 + x * 1e-7, -1e9 + y * 1e-7) for x, y in grid(12, 9, 1.0, 2)],
    "polygon64": polygon(64, 1.0, (0.0, 0.0), True),
    "polygon17": polygon(17, 2.5, (3.0, -1.0), False),
    "circles": lattice_circles([5, 25, 65], (0.5, 1000.0)),
    "lattice": lattice_subset(24, 20, 0.5, 3),
    "uniform": uniform(400, 4),
}


def write_node(path, pts):
    with open(path, "w") as f:
        f.write(f"{len(pts)} 2 0 0\n")
        for k, (x, y) in enumerate(pts, 1):
            f.write(f"{k} {x!r} {y!r}\n")


def read_triangles(path):
    with open(path) as f:
        rows = [line.split() for line in f if line.strip() and not line.startswith("#")]
    tris = set()
    for row in rows[1:]:
        t = [int(v) for v in row[1:4]]
        k = t.index(min(t))
        tris.add(tuple(t[k:] + t[:k]))
    return tris


def det(m):
    """Exact determinant by cofactor expansion (small matrices of Fractions)."""
    if len(m) == 1:
        return m[0][0]
    return sum((-1) ** j * m[0][j] * det([row[:j] + row[j + 1:] for row in m[1:]]) for j in range(len(m)))


def perturbed_inside(a, b, c, d):
    """Sign of the lifted 4x4 determinant of a, b, c, d (positive: d inside the circle of the
    counter-clockwise a, b, c) with lifts lowered by eps^rank, for an infinitesimal eps."""
    pts = [a, b, c, d]
    rows = [[p[0], p[1], p[0] * p[0] + p[1] * p[1], Fraction(1)] for p in pts]
    d0 = det(rows)
    if d0 != 0:
        return 1 if d0 > 0 else -1
    for k in sorted(range(4), key=lambda i: pts[i]):
        unit = [[r[0], r[1], Fraction(1 if i == k else 0), r[3]] for i, r in enumerate(rows)]
        coefficient = -det(unit)  # of eps^rank(k)
        if coefficient != 0:
            return 1 if coefficient > 0 else -1
    return 0


def perturbed_faults(pts, tris):
    exact = {i + 1: (Fraction(x), Fraction(y)) for i, (x, y) in enumerate(pts)}
    apex = {}
    for t in tris:
        for i in range(3):
            apex[(t[i], t[(i + 1) % 3])] = t[(i + 2) % 3]
    bad = 0
    for (u, v), w in apex.items():
        if u < v and (v, u) in apex:
            if perturbed_inside(exact[u], exact[v], exact[w], exact[apex[(v, u)]]) >= 0:
                bad += 1
    return bad


def main():
    deltri, work = sys.argv[1], sys.argv[2]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    failures = 0
    for name, pts in SETS.items():
        node = os.path.join(work, name + ".node")
        write_node(node, pts)
        results = {}
        for switch in ["-C", "-lC", "-iC", "-FC"]:
            run = subprocess.run([deltri, "-Q" + switch[1:], node], capture_output=True, text=True)
            if run.returncode != 0:
                print(f"{name} {switch}: exit status {run.returncode}: {run.stderr.strip()}")
                failures += 1
                continue
            results[switch] = read_triangles(os.path.join(work, name + ".1.ele"))
        reference = results.get("-C", set())
        differ = [switch for switch, tris in results.items() if tris != reference]
        for switch in differ:
            print(f"{name}: {switch} gives {len(results[switch] ^ reference)} triangles not in both it and divide and conquer's")
        faults = perturbed_faults(pts, reference)
        if faults:
            print(f"{name}: {faults} edges not locally Delaunay under the perturbation")
        failures += len(differ) + (faults > 0)
        if not differ and not faults and len(results) == 4:
            print(f"{name}: {len(pts)} points, {len(reference)} triangles, the same from -C -lC -iC -FC, the perturbed Delaunay triangulation")
    if failures:
        print(f"{failures} failures")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
