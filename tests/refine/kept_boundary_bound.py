#!/usr/bin/env python3
"""With -Y / -YY, no output angle may lie below the floor the fixed boundary certainly allows.

    kept_boundary_bound.py DELTRI INPUT.poly SWITCHES    (SWITCHES such as -pYYq or -pYYq33)

The floor is min(q, m), where q is the -q angle (20 when bare) and m the smallest angle of the
input's constrained Delaunay triangulation, read from `DELTRI -p` (triangulation only, no
refinement). That triangulation keeps every segment whole and adds no vertex, so it is a mesh the
fixed boundary allows: a -Y mesh with a smaller angle is worse than the input's own triangulation.
With -YY deltri guarantees the floor (docs/refinement.md, "-Y, -YY"). Angles are computed here from
the written .node/.ele in doubles; nothing deltri reports about quality is used.

Also fails when the run fails. Exit 0 when the check passes, 1 otherwise. On main before
issue 16 (9e54440) debug2.poly -pYYq33 failed: 0.0111 degrees against a floor of 0.0180 (Triangle
1.6: 0.0123), and water-huge.poly -pYYq33: 0.0307 against 0.1282.
"""
import math, os, re, shutil, subprocess, sys, tempfile


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
    return pts, tris


def smallest_angle(pts, tris):
    smallest, where = 180.0, None
    for t in tris:
        a, b, c = pts[t[0]], pts[t[1]], pts[t[2]]
        m = min(angle_at(a, b, c), angle_at(b, c, a), angle_at(c, a, b))
        if m < smallest: smallest, where = m, t
    return smallest, where


def main():
    deltri, inp, switches = sys.argv[1:4]
    q = re.search(r'q([0-9.]*)', switches)
    theta = float(q.group(1)) if q and q.group(1) else 20.0
    d = tempfile.mkdtemp()
    try:
        pts0, tris0 = run(deltri, inp, '-p', d)
        m, _ = smallest_angle(pts0, tris0)
        pts, tris = run(deltri, inp, switches, d)
    finally:
        shutil.rmtree(d)
    name = os.path.basename(inp)
    floor = min(theta, m)
    smallest, where = smallest_angle(pts, tris)
    ok = smallest >= floor * (1 - 1e-9)
    print(f'{"ok" if ok else "FAIL"}: {name} {switches}: smallest angle {smallest:.4f} (triangle {where}), floor '
          f'{floor:.4f} = min(q {theta:g}, initial triangulation {m:.4f}); {len(tris)} triangles')
    return 0 if ok else 1


sys.exit(main())
