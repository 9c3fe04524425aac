#!/usr/bin/python3
"""Independent check of deltri's surface meshes (facets in 3-D, TetGen .poly/.smesh input).

usage: check_surface.py DELTRI INPUT_DIR

For each input and each switch set it runs deltri, reads the .node/.ele/.edge back with its own
parser and checks, from the input facets alone (numpy, no deltri code):
  * every triangle lies in the plane of a facet with its marker (corners within 1e-9 of the facet's
    size) and inside the bounding box of that facet;
  * per marker, the triangles' areas sum to the facets' areas (polygon areas from the input: the
    loops not inside another loop, minus the inner loops around a hole point) to 1e-9 relative;
  * conformity: an edge lying along an input segment is in exactly as many triangles as there are
    facets holding that segment on their border (two for a facet holding it inside, as a 2-point
    polygon), any other edge in exactly two; for closed inputs every edge is
    in exactly two triangles (watertight);
  * no angle below the -q bound, except a triangle whose smallest angle is at an input point where
    a facet's polygon has a corner angle below 60 degrees, and is no smaller than that angle (only
    wedge.poly has such corners: 15 degrees, and the two TetGen surfaces, whose facets are triangles);
  * -a: no triangle larger than the bound;
  * --msh, --vtu, --stl and -g (OFF) read back by meshio with the same points and triangles, and
    gmsh opens the .msh; the .msh's physical tags follow the documented rule (docs/formats.md,
    "Physical groups") from the .ele's facet markers: a positive marker is its own tag, 0 and
    negative markers the next tags in ascending order, each group named "marker <value>".
"""
import math
import os
import shutil
import subprocess
import sys
import tempfile

try:
    import numpy as np
except ImportError:  # main() reports the test as skipped, with the command that installs numpy
    np = None

CLOSED = {"cube.smesh", "cube_markers.smesh", "l_bracket.poly", "slot_box.poly", "wedge.poly", "pynastran_gear.smesh", "pynastran_sphere.smesh"}
INPUTS = ["cube.smesh", "cube_markers.smesh", "l_bracket.poly", "tee.poly", "slot_box.poly", "wedge.poly", "pynastran_gear.smesh",
          "pynastran_sphere.smesh", "house.poly"]
# the area bound of the third switch set, for the inputs whose size is not about 1 (the gear is 59 wide)
AREA = {"pynastran_gear.smesh": 50.0}


def switches(name):
    a = AREA.get(name, 0.02)
    return [("-pq20C", 20, None), ("-pq30C", 30, None), (f"-pq30a{a:g}C", 30, a)]

failures = []


def fail(msg):
    failures.append(msg)
    print("FAIL:", msg)


def data_lines(path):
    with open(path) as f:
        for line in f:
            line = line.split("#")[0].replace(",", " ").split()
            if line:
                yield line


def read_points(it, n):
    pts = []
    first = None
    for _ in range(n):
        l = next(it)
        if first is None:
            first = int(l[0])
        pts.append([float(l[1]), float(l[2]), float(l[3])])
    return np.array(pts), first


def companion_node(path):
    """TetGen's layout: a node count of 0 means the points are in <base>.node."""
    return path.rsplit(".", 1)[0] + ".node"


def read_facets(path):
    it = data_lines(path)
    head = next(it)
    n = int(head[0])
    if n == 0:
        nodes = data_lines(companion_node(path))
        pts, first = read_points(nodes, int(next(nodes)[0]))
    else:
        pts, first = read_points(it, n)
    l = next(it)
    nf, fmark = int(l[0]), len(l) > 1 and int(l[1]) != 0
    facets = []
    for _ in range(nf):
        l = next(it)
        if path.endswith(".smesh"):
            k = int(l[0])
            poly = [int(x) - first for x in l[1:1 + k]]
            m = int(l[1 + k]) if fmark and len(l) > 1 + k else 0
            facets.append((m, [poly], []))
            continue
        npoly = int(l[0])
        nh = int(l[1]) if len(l) > 1 else 0
        m = int(l[2]) if fmark and len(l) > 2 else 0
        polys = []
        for _ in range(npoly):
            q = next(it)
            k = int(q[0])
            polys.append([int(x) - first for x in q[1:1 + k]])
        holes = [np.array([float(x) for x in next(it)[1:4]]) for _ in range(nh)]
        facets.append((m, polys, holes))
    return pts, facets


def frame(pts, polys):
    ids = [v for p in polys for v in p]
    P = pts[ids]
    c = P.mean(axis=0)
    # the normal: singular vector of the smallest singular value (least-squares plane)
    _, _, vt = np.linalg.svd(P - c)
    n = vt[2]
    u = vt[0]
    v = np.cross(n, u)
    return c, u, v, n


def shoelace(q):
    x, y = q[:, 0], q[:, 1]
    return 0.5 * float(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1)))


def inside(pt, q):
    x, y = pt
    c = False
    for i in range(len(q)):
        x1, y1 = q[i]
        x2, y2 = q[(i + 1) % len(q)]
        if (y1 > y) != (y2 > y) and x < x1 + (y - y1) * (x2 - x1) / (y2 - y1):
            c = not c
    return c


def facet_area(pts, polys, holes, fr):
    c, u, v, n = fr
    loops = [np.array([[np.dot(pts[i] - c, u), np.dot(pts[i] - c, v)] for i in p]) for p in polys if len(p) >= 3]
    hp = [np.array([np.dot(h - c, u), np.dot(h - c, v)]) for h in holes]
    area = 0.0
    for k, q in enumerate(loops):
        a = abs(shoelace(q))
        probe = q.mean(axis=0) if len(q) > 0 else None
        in_other = any(inside(q[0] * (1 - 1e-9) + probe * 1e-9, loops[j]) for j in range(len(loops)) if j != k)
        around_hole = any(inside(h, q) for h in hp)
        if not in_other:
            area += a
        elif around_hole:
            area -= a
    return area


def small_input_angles(pts, facets):
    """Input point -> the smallest polygon corner angle below 60 degrees there (unsigned, so a
    reflex corner counts by its exterior angle: lenient)."""
    small = {}
    for m, polys, holes in facets:
        for p in polys:
            if len(p) < 3:
                continue
            for i in range(len(p)):
                o, a, b = pts[p[i]], pts[p[i - 1]], pts[p[(i + 1) % len(p)]]
                u, w = a - o, b - o
                ang = math.degrees(math.atan2(np.linalg.norm(np.cross(u, w)), np.dot(u, w)))
                if ang < 60:
                    small[p[i]] = min(small.get(p[i], 180.0), ang)
    return small


def read_table(path, cols):
    it = data_lines(path)
    head = next(it)
    n = int(head[0])
    rows = [next(it) for _ in range(n)]
    return head, rows


def check_run(deltri, inp, work, sw, q, amax):
    name = os.path.basename(inp)
    base = os.path.join(work, name.rsplit(".", 1)[0])
    shutil.copy(inp, work)
    if os.path.exists(companion_node(inp)):
        shutil.copy(companion_node(inp), work)
    args = [deltri, sw, "--msh", "--vtu", "--stl", "-g", "-Q", os.path.join(work, name)]
    r = subprocess.run(args, capture_output=True, text=True)
    tag = f"{name} {sw}"
    if r.returncode != 0:
        fail(f"{tag}: exit {r.returncode}: {r.stderr.strip()}")
        return
    pts_in, facets = read_facets(inp)
    _, nrows = read_table(base + ".1.node", 4)
    P = np.array([[float(x) for x in row[1:4]] for row in nrows])
    first = int(nrows[0][0])
    _, erows = read_table(base + ".1.ele", 5)
    T = np.array([[int(x) - first for x in row[1:4]] for row in erows])
    M = np.array([int(row[4]) for row in erows])
    # input points keep their coordinates
    if not np.array_equal(P[: len(pts_in)], pts_in):
        fail(f"{tag}: input points moved in the .node")
    frames = [frame(pts_in, f[1]) for f in facets]
    sizes = [np.ptp(pts_in[[v for p in f[1] for v in p]], axis=0).max() for f in facets]
    A, B, C = P[T[:, 0]], P[T[:, 1]], P[T[:, 2]]
    tri_area = 0.5 * np.linalg.norm(np.cross(B - A, C - A), axis=1)
    if (tri_area <= 0).any():
        fail(f"{tag}: degenerate triangles")
    # 1. each triangle in the plane (and box) of a facet with its marker (the first such facet
    # takes it; vectorised over the triangles, one facet at a time)
    unplaced = np.ones(len(T), dtype=bool)
    for k, (m, polys, holes) in enumerate(facets):
        c, u, v, n = frames[k]
        tol = 1e-9 * sizes[k]
        ids = [w for p in polys for w in p]
        lo, hi = pts_in[ids].min(axis=0) - tol, pts_in[ids].max(axis=0) + tol
        ok = unplaced & (M == m)
        for X in (A, B, C):
            ok &= (np.abs((X - c) @ n) <= tol) & (X >= lo).all(axis=1) & (X <= hi).all(axis=1)
        unplaced &= ~ok
    if unplaced.any():
        t = int(np.argmax(unplaced))
        fail(f"{tag}: triangle {t + first} lies in no facet with marker {M[t]}")
    for m in sorted(set(f[0] for f in facets)):
        want = sum(facet_area(pts_in, f[1], f[2], frames[k]) for k, f in enumerate(facets) if f[0] == m)
        got = tri_area[M == m].sum()
        if abs(got - want) > 1e-9 * max(1.0, want):
            fail(f"{tag}: marker {m}: triangles cover {got!r}, the facets {want!r}")
    # 2. conformity along segments, watertightness
    # segment -> the triangles expected on each of its edges: one per facet whose polygon edge it
    # is, two per facet that holds it as a 2-point polygon (a segment inside the facet)
    seg_facets = {}
    for k, (m, polys, holes) in enumerate(facets):
        for p in polys:
            e = len(p) if len(p) >= 3 else (1 if len(p) == 2 else 0)
            for i in range(e):
                a, b = p[i], p[(i + 1) % len(p)]
                seg_facets.setdefault((min(a, b), max(a, b)), {})[k] = 2 if len(p) == 2 else 1
    edges = {}
    for t in T:
        for i in range(3):
            a, b = int(t[i]), int(t[(i + 1) % 3])
            key = (min(a, b), max(a, b))
            edges[key] = edges.get(key, 0) + 1
    segs = list(seg_facets.items())
    S0 = np.array([pts_in[s[0][0]] for s in segs])
    S1 = np.array([pts_in[s[0][1]] for s in segs])
    D = S1 - S0
    L2 = (D * D).sum(axis=1)
    bad = 0
    for (a, b), count in edges.items():
        expected = 2
        ta = ((P[a] - S0) * D).sum(axis=1) / L2
        tb = ((P[b] - S0) * D).sum(axis=1) / L2
        da = np.linalg.norm(S0 + ta[:, None] * D - P[a], axis=1)
        db = np.linalg.norm(S0 + tb[:, None] * D - P[b], axis=1)
        tol = 1e-9 * np.sqrt(L2)
        on = (da <= tol) & (db <= tol) & (ta >= -1e-12) & (ta <= 1 + 1e-12) & (tb >= -1e-12) & (tb <= 1 + 1e-12)
        if on.any():
            expected = sum(segs[int(np.argmax(on))][1].values())
        if name in CLOSED and count != 2:
            fail(f"{tag}: edge {a + first}-{b + first} is in {count} triangles (closed input: must be 2)")
            bad += 1
        elif count != expected:
            fail(f"{tag}: edge {a + first}-{b + first} is in {count} triangles, {expected} expected")
            bad += 1
        if bad > 5:
            break
    # 3. angles
    def angles(X, Y, Z):
        a, b = Y - X, Z - X
        return np.degrees(np.arctan2(np.linalg.norm(np.cross(a, b), axis=1), (a * b).sum(axis=1)))
    an = np.stack([angles(A, B, C), angles(B, C, A), angles(C, A, B)], axis=1)
    small_corner = small_input_angles(pts_in, facets)
    excused = 0
    for t in np.where(an.min(axis=1) < q - 1e-9)[0]:
        i = int(np.argmin(an[t]))
        v = int(T[t][i])
        if v in small_corner and an[t][i] >= small_corner[v] - 1e-9:
            excused += 1
            continue
        fail(f"{tag}: triangle {t + first} has an angle of {an[t].min():.4f} < {q}, not at a small input angle")
        break
    smallest = an.min()
    if amax is not None and tri_area.max() > amax * (1 + 1e-9):
        fail(f"{tag}: a triangle of area {tri_area.max()} > {amax}")
    # 4. other formats
    check_formats(tag, base, P, T, M)
    print(f"ok {tag}: {len(T)} triangles, smallest angle {smallest:.2f}, {len(edges)} edges"
          + (f", {excused} below {q} at small input angles" if excused else ""))


def rule_tags(markers):
    """The physical tag of each marker by the documented rule (docs/formats.md, "Physical groups"):
    a marker from 1 to 999999999 is its own tag, a marker m from -147483647 to 0 is 2000000000 - m,
    any other the next tag from 1900000000 up in ascending order."""
    tags, other = {}, 1900000000
    for v in sorted(set(markers)):
        if 1 <= v <= 999999999:
            tags[v] = v
        elif -147483647 <= v <= 0:
            tags[v] = 2000000000 - v
        else:
            tags[v], other = other, other + 1
    return tags


def check_physical(tag, path, T, M):
    import meshio
    m = meshio.read(path)
    tags = rule_tags(M.tolist())
    names = {f"marker {v}": (t, 2) for v, t in tags.items()}
    got = {k: (int(v[0]), int(v[1])) for k, v in m.field_data.items()}
    if got != names:
        fail(f"{tag}: the .msh's $PhysicalNames {got}, the rule gives {names}")
    tri = np.concatenate([c.data for c in m.cells if c.type == "triangle"])
    phys = np.concatenate([p for c, p in zip(m.cells, m.cell_data["gmsh:physical"]) if c.type == "triangle"])
    got = sorted((tuple(sorted(c)), int(p)) for c, p in zip(tri.tolist(), phys))
    want = sorted((tuple(sorted(c)), tags[int(k)]) for c, k in zip(T.tolist(), M))
    if got != want:
        fail(f"{tag}: the .msh's physical tags are not the .ele's facet markers by the rule")


def check_formats(tag, base, P, T, M):
    import meshio
    key = sorted(map(tuple, np.sort(T, axis=1)))
    check_physical(tag, f"{base}.1.msh", T, M)
    for ext in ("msh", "vtu", "stl", "off"):
        path = f"{base}.1.{ext}"
        m = meshio.read(path)
        tri = np.concatenate([c.data for c in m.cells if c.type == "triangle"])
        if ext == "stl":  # STL repeats coordinates per triangle; meshio merges equal points
            got = sorted(tuple(sorted(map(tuple, np.round(m.points[t], 12)))) for t in tri)
            want = sorted(tuple(sorted(map(tuple, np.round(P[t], 12)))) for t in T)
            if got != want:
                fail(f"{tag}: the .stl has other triangles than the .ele")
            continue
        if not np.allclose(m.points[:, :3], P, rtol=0, atol=0):
            fail(f"{tag}: the .{ext} has other points than the .node")
        if sorted(map(tuple, np.sort(tri, axis=1))) != key:
            fail(f"{tag}: the .{ext} has other triangles than the .ele")
    r = subprocess.run(["gmsh", "-check", f"{base}.1.msh"], capture_output=True, text=True, timeout=120)
    if r.returncode != 0 or "rror" in r.stdout + r.stderr:
        fail(f"{tag}: gmsh -check on the .msh: {(r.stdout + r.stderr)[-300:]}")


def check_errors(deltri, indir, work):
    shutil.copy(os.path.join(indir, "nonplanar.poly"), work)
    r = subprocess.run([deltri, "-pq30", os.path.join(work, "nonplanar.poly")], capture_output=True, text=True)
    want = "nonplanar.poly:9: facet 1: not planar"
    if r.returncode != 1 or want not in r.stderr or os.path.exists(os.path.join(work, "nonplanar.1.node")):
        fail(f"nonplanar.poly: exit {r.returncode}, stderr {r.stderr.strip()!r}: expected exit 1 and '{want}'")
    else:
        print("ok nonplanar.poly refused:", r.stderr.strip())
    # malformed files: one line naming the file and line, exit 1, no output
    bad = {
        "corner.poly": ("4 3 0 0\n1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n1 0\n1\n4 1 2 3 5\n", "corner.poly:8: facet 1: corner 5 is not a point"),
        "short.smesh": ("3 3\n1 0 0 0\n2 1 0 0\n3 0 1 0\n2 0\n3 1 2 3\n", "short.smesh:6: unexpected end of file: 2 facets announced, 1 complete"),
        "line.poly": ("3 3\n1 0 0 0\n2 1 0 0\n3 2 0 0\n1\n1\n3 1 2 3\n", "line.poly:6: facet 1: its points are collinear"),
    }
    for name, (text, want) in bad.items():
        path = os.path.join(work, name)
        with open(path, "w") as f:
            f.write(text)
        r = subprocess.run([deltri, "-pq30", path], capture_output=True, text=True)
        outputs = [x for x in os.listdir(work) if x.startswith(name.split(".")[0] + ".1.")]
        if r.returncode != 1 or want not in r.stderr or outputs or len(r.stderr.strip().splitlines()) != 1:
            fail(f"{name}: exit {r.returncode}, stderr {r.stderr.strip()!r}, outputs {outputs}: expected exit 1 and '{want}'")
        else:
            print(f"ok {name} refused:", r.stderr.strip())


def has_meshio():
    try:
        import meshio  # noqa: F401
    except ImportError:
        return False
    return True


def main():
    deltri, indir = sys.argv[1], sys.argv[2]
    missing = [package for package, there in (("python3-numpy", np is not None), ("python3-meshio", has_meshio()),
                                              ("gmsh", shutil.which("gmsh") is not None)) if not there]
    if missing:  # exit 77: CTest reports the test as skipped (make test installs these where it can)
        print(f"SKIP: missing {', '.join(missing)}; install with: sudo apt-get install -y {' '.join(missing)}")
        return 77
    with tempfile.TemporaryDirectory() as work:
        for name in INPUTS:
            for sw, q, amax in switches(name):
                check_run(deltri, os.path.join(indir, name), work, sw, q, amax)
        check_errors(deltri, indir, work)
    print(f"{len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
