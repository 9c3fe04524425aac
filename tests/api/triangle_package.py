"""The `triangle` package's documented examples with `import deltri as tr` (issue 46): the calls of
its API page and of its example scripts (doc/plot/*.py of drufat/triangle: delaunay, convex_hull,
voronoi, triangulate of points, of PSLGs with holes and regions, r with per-triangle bounds,
get_data and loads, plot and compare to a file with matplotlib's Agg backend), each call as the
examples make it, on samples of the same names that this test writes itself (the package's own
samples are not ours to ship; docs/library.md). Every mesh is checked independently:
deltri_mesh_verify on the input and the mesh written as files (conformity, segments, holes, angle
and area bounds), tests/tools/exact_delaunay_check.py (exact rationals) for the Delaunay property
and convex hulls, and facts computed here (areas, the API page's documented results as sets, the
Voronoi vertices as circumcentres). A bad switch string raises ValueError; plotting without
matplotlib raises ImportError naming the package to install.
    DELTRI_LIBRARY=... PYTHONPATH=src/api/python triangle_package.py DELTRI VERIFY SOURCE_DIR"""
import math
import os
import shutil
import subprocess
import sys
import tempfile
from fractions import Fraction

import numpy as np

try:
    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt
except ImportError:
    print('SKIP: missing python3-matplotlib; install with: sudo apt-get install -y python3-matplotlib')
    sys.exit(77)

import deltri as tr  # the examples say `import triangle as tr`
from apitest import check, finish, write_files, write_poly

DELTRI, VERIFY, SOURCE = sys.argv[1:4]
WORK = tempfile.mkdtemp()
DATA = os.path.join(WORK, 'data')


# ---- independent facts ----

def orient(a, b, c):
    a, b, c = ([Fraction(float(x)) for x in p] for p in (a, b, c))
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])


def areas(m):
    p = np.asarray(m['vertices'])[np.asarray(m['triangles'])[:, :3]]
    return 0.5 * ((p[:, 1, 0] - p[:, 0, 0]) * (p[:, 2, 1] - p[:, 0, 1]) - (p[:, 1, 1] - p[:, 0, 1]) * (p[:, 2, 0] - p[:, 0, 0]))


def hull_area(points):
    """The area of the convex hull of points, its edges (convex_hull) walked as a cycle."""
    points = np.asarray(points, dtype=np.float64)
    following = dict(tr.convex_hull(points).tolist())
    cycle = [next(iter(following))]
    while len(cycle) < len(following):
        cycle.append(following[cycle[-1]])
    return abs(polygon_area([tuple(points[k]) for k in cycle]))


def polygon_area(points):
    return 0.5 * sum(x0 * y1 - x1 * y0 for (x0, y0), (x1, y1) in zip(points, points[1:] + points[:1]))


def verify(name, given, m, *options):
    """deltri_mesh_verify on the input dict and the mesh; the exact checker where the options say
    the mesh is Delaunay (--delaunay: no segment constrains it) or spans the hull."""
    stem = os.path.join(WORK, name)
    if '--refined' in options and 'segments' not in given:
        # q or a on points: the hull's edges are segments (split by the refinement), so the
        # verifier reads the input as the points with their hull as segments.
        given = dict(given, segments=tr.convex_hull(given['vertices']))
    # A point set is given as a .node, a PSLG as a .poly.
    source = stem + ('.poly' if 'segments' in given else '.in.node')
    write_poly(stem + '.poly', given)
    write_files(stem + '.in', given)
    write_files(stem + '.1', m)
    flags = [o for o in options if o != '--delaunay']
    run = subprocess.run([VERIFY, '--input', source, '--mesh', stem + '.1'] + flags, capture_output=True, text=True)
    check(run.returncode == 0, '%s: deltri_mesh_verify %s: %d triangles%s' %
          (name, ' '.join(flags), len(m['triangles']), '' if run.returncode == 0 else ': ' + run.stdout.strip()))
    if '--delaunay' in options:
        if os.path.exists(stem + '.1.poly'):
            os.remove(stem + '.1.poly')
        exact = [sys.executable, os.path.join(SOURCE, 'tests/tools/exact_delaunay_check.py'), stem + '.1']
        if '--convex-hull' in options:
            exact += ['--convex-hull', stem + '.in.node']
        run = subprocess.run(exact, capture_output=True, text=True)
        check(run.returncode == 0, '%s: exact Delaunay check%s: %s' %
              (name, ' and convex hull' if '--convex-hull' in options else '', run.stdout.strip()))


def same_sets(got, documented):
    return sorted(sorted(r) for r in np.asarray(got).tolist()) == sorted(sorted(r) for r in documented)


def saved(name):
    path = os.path.join(WORK, name + '.png')
    plt.savefig(path)
    plt.close('all')
    check(os.path.getsize(path) > 1000, '%s: plotted to %s' % (name, os.path.basename(path)))


# ---- the samples, written here under the package's names ----

def write(name, text):
    with open(os.path.join(DATA, name), 'w') as f:
        f.write(text)


def poly_text(vertices, segments, holes, regions, markers=False):
    out = ['%d 2 0 %d' % (len(vertices), int(markers))]
    out += ['%d %r %r%s' % (k + 1, x, y, ' 1' if markers else '') for k, (x, y) in enumerate(vertices)]
    out += ['%d %d' % (len(segments), int(markers))]
    out += ['%d %d %d%s' % (k + 1, a + 1, b + 1, ' %d' % (k + 2) if markers else '') for k, (a, b) in enumerate(segments)]
    out += ['%d' % len(holes)] + ['%d %r %r' % (k + 1, x, y) for k, (x, y) in enumerate(holes)]
    out += ['%d' % len(regions)] + ['%d %s' % (k + 1, ' '.join('%r' % v for v in r)) for k, r in enumerate(regions)]
    return '# written by tests/api/triangle_package.py\n' + '\n'.join(out) + '\n'


def loop(first, count):
    return [(first + k, first + (k + 1) % count) for k in range(count)]


A_OUTER = [(0.0, 0.0), (1.0, 0.0), (1.3, 1.0), (2.7, 1.0), (3.0, 0.0), (4.0, 0.0), (2.5, 5.0), (1.5, 5.0)]
A_HOLE = [(1.5, 2.0), (2.5, 2.0), (2.0, 3.0)]
FACE_OUTER = [(0.0, 0.0), (4.0, 0.0), (5.0, 1.0), (5.0, 5.0), (4.0, 6.0), (0.0, 6.0), (-1.0, 5.0), (-1.0, 1.0)]
FACE_LOOPS = [[(0.5, 3.5), (1.5, 3.5), (1.5, 4.5), (0.5, 4.5)], [(2.5, 3.5), (3.5, 3.5), (3.5, 4.5), (2.5, 4.5)],
              [(1.0, 1.0), (3.0, 1.0), (3.0, 2.0), (1.0, 2.0)]]
LA_TOP = [(0.0, -1.0), (5.0, -2.0), (10.0, -1.5)]
LA_LOW = [(0.0, -3.0), (5.0, -3.5), (10.0, -3.0)]
LA_BOUNDS = [0.2, 0.5, 1.0]  # top, middle, bottom layer


def make_samples():
    os.makedirs(DATA)
    write('A.poly', poly_text(A_OUTER + A_HOLE, loop(0, 8) + loop(8, 3), [(2.0, 2.4)], []))
    state, dots = 12345, set()
    while len(dots) < 100:  # a fixed linear congruential sequence, 3 decimals
        state = (state * 1103515245 + 12345) % 2 ** 31
        x = round((state % 100003) / 100003.0, 3)
        state = (state * 1103515245 + 12345) % 2 ** 31
        dots.add((x, round((state % 100019) / 100019.0, 3)))
    dots = sorted(dots)
    write('dots.node', '100 2 0 0\n' + ''.join('%d %r %r\n' % (k + 1, x, y) for k, (x, y) in enumerate(dots)))
    spiral = [(round((0.2 + 0.1 * k) * math.cos(0.6 * k), 4), round((0.2 + 0.1 * k) * math.sin(0.6 * k), 4)) for k in range(15)]
    write('spiral.node', '15 2 0 0\n' + ''.join('%d %r %r\n' % (k + 1, x, y) for k, (x, y) in enumerate(spiral)))
    face_v = FACE_OUTER + sum(FACE_LOOPS, []) + [(1.7, 2.6), (1.9, 3.1), (2.3, 2.6), (2.1, 3.1), (0.2, 2.5), (3.8, 2.5)]
    face_s = loop(0, 8) + loop(8, 4) + loop(12, 4) + loop(16, 4) + [(20, 21), (22, 23)]
    write('face.poly', poly_text(face_v, face_s, [(1.0, 4.0), (3.0, 4.0), (2.0, 1.5)], []))
    box_v = [(0.0, 0.0), (3.0, 0.0), (3.0, 3.0), (0.0, 3.0), (1.0, 1.0), (2.0, 1.0), (2.0, 2.0), (1.0, 2.0)]
    write('box.poly', poly_text(box_v, [(3, 0)] + loop(4, 4), [(1.5, 1.5)], [], markers=True))
    la_v = [(0.0, 0.0), (10.0, 0.0), (10.0, -5.0), (0.0, -5.0)] + LA_TOP + LA_LOW
    la_s = loop(0, 4) + [(4, 5), (5, 6), (7, 8), (8, 9)]
    # One value after x and y on each region line, as in the package's la.poly.
    write('la.poly', poly_text(la_v, la_s, [], [(5.0, -0.5, 0.2), (5.0, -2.7, 0.5), (5.0, -4.5, 1.0)]))
    # bbox.1, face.1 and diamond_02_00009.1.v: written by the command line, read by get_data.
    run = lambda switches, name: subprocess.run([DELTRI, switches, name], cwd=DATA, check=True, capture_output=True)
    run('-pcQ', 'box.poly')
    for ext in ('node', 'ele'):
        os.rename(os.path.join(DATA, 'box.1.' + ext), os.path.join(DATA, 'bbox.1.' + ext))
    os.remove(os.path.join(DATA, 'box.1.poly'))
    t = int(open(os.path.join(DATA, 'bbox.1.ele')).readline().split()[0])
    write('bbox.1.area', '%d\n' % t + ''.join('%d %r\n' % (k + 1, -1.0 if k % 3 == 0 else 0.1 * (k % 4 + 1)) for k in range(t)))
    run('-pQ', 'face.poly')
    diamond = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0), (0.5, 0.5), (0.25, 0.3), (0.7, 0.2), (0.6, 0.8), (0.3, 0.75)]
    write('diamond_02_00009.node', '9 2 0 0\n' + ''.join('%d %r %r\n' % (k + 1, x, y) for k, (x, y) in enumerate(diamond)))
    run('-vQ', 'diamond_02_00009.node')


# ---- the examples ----

def api_page():
    """The API page's examples and their documented results (Triangle's own answers), as sets."""
    square = [[0, 0], [0, 1], [1, 1], [1, 0]]
    t = tr.triangulate({'vertices': square}, 'a0.2')
    documented = [[0.0, 0.0], [0.0, 1.0], [1.0, 1.0], [1.0, 0.0], [0.5, 0.5], [0.0, 0.5], [0.5, 0.0], [1.0, 0.5], [0.5, 1.0]]
    check(t['vertices'].tolist() == documented and t['vertex_markers'].tolist() == [[1], [1], [1], [1], [0], [1], [1], [1], [1]],
          "triangulate({'vertices': v}, 'a0.2'): the documented vertices and markers")
    check(same_sets(t['triangles'], [[7, 2, 4], [5, 0, 4], [4, 8, 1], [4, 1, 5], [4, 0, 6], [6, 3, 4], [4, 3, 7], [4, 2, 8]]),
          "triangulate(..., 'a0.2'): the documented triangles (as sets)")
    pts = [[0, 0], [0, 1], [0.5, 0.5], [1, 1], [1, 0]]
    d = tr.delaunay(pts)
    check(same_sets(d, [[1, 0, 2], [2, 4, 3], [4, 2, 0], [2, 3, 1]]) and all(orient(*[pts[i] for i in r]) > 0 for r in d.tolist()),
          'delaunay(pts): the documented triangles, counter-clockwise')
    check(same_sets(tr.convex_hull(square), [[3, 0], [2, 3], [1, 2], [0, 1]]), 'convex_hull(pts): the documented segments')
    points, edges, origins, directions = tr.voronoi(pts)
    geometric = sorted(tuple(sorted(tuple(points[i]) for i in e)) for e in edges.tolist())
    rays = sorted((tuple(points[o]), tuple(d)) for o, d in zip(origins.tolist(), directions.tolist()))
    documented_edges = [((0.0, 0.5), (0.5, 0.0)), ((0.0, 0.5), (0.5, 1.0)), ((1.0, 0.5), (0.5, 0.0)), ((1.0, 0.5), (0.5, 1.0))]
    check(sorted(map(tuple, points.tolist())) == sorted([(0.0, 0.5), (1.0, 0.5), (0.5, 0.0), (0.5, 1.0)]) and origins.ndim == 1 and
          geometric == sorted(tuple(sorted(e)) for e in documented_edges) and
          rays == sorted([((0.0, 0.5), (-1.0, 0.0)), ((1.0, 0.5), (1.0, 0.0)), ((0.5, 0.0), (0.0, -1.0)), ((0.5, 1.0), (0.0, 1.0))]),
          'voronoi(pts): the documented points, edges and rays (as geometry)')
    A = dict(vertices=np.array(square))
    tr.compare(plt, A, tr.triangulate(A, 'a0.2'))
    saved('api_triangulate')
    tr.compare(plt, dict(vertices=np.array(pts)), dict(vertices=np.array(pts), triangles=d))
    saved('api_delaunay')
    tr.compare(plt, dict(vertices=np.array(pts)), dict(vertices=points, edges=edges, ray_origins=origins, ray_directions=directions))
    saved('api_voronoi')
    ax = plt.axes()
    tr.plot(ax, vertices=np.array(pts))
    lim = ax.axis()
    tr.plot(ax, vertices=points, edges=edges, ray_origins=origins, ray_directions=directions)
    ax.axis(lim)
    saved('voronoi3')


def point_examples():
    """ex1 to ex5: a square and a 32-gon's points, triangulated plain, with q and with a."""
    square = dict(vertices=np.array(((0, 0), (1, 0), (1, 1), (0, 1))))
    theta = np.linspace(0, 2 * np.pi, 32, endpoint=False)
    circle = dict(vertices=np.stack([np.cos(theta), np.sin(theta)], axis=1))
    for name, A, opts, extra in (('ex1', square, '', ['--delaunay']), ('ex2', square, 'qa0.1', ['--min-angle', '20', '--max-area', '0.1']),
                                 ('ex3', square, 'qa0.01', ['--min-angle', '20', '--max-area', '0.01']),
                                 ('ex4', circle, 'q', ['--min-angle', '20']), ('ex5', circle, 'qa0.05', ['--min-angle', '20', '--max-area', '0.05'])):
        B = tr.triangulate(A, opts) if opts else tr.triangulate(A)
        # A refined mesh of points spans the hull, with vertices on its edges (the area below).
        verify(name, A, B, *(extra + (['--refined'] if opts else ['--convex-hull'])))
        hull = hull_area(A['vertices'])
        check(math.isclose(areas(B).sum(), hull, rel_tol=1e-12), '%s: the triangles cover the hull (area %.12g)' % (name, hull))
        tr.compare(plt, A, B)
        saved(name)


def hole_and_region_examples():
    """ex6: an annulus (segments, a hole) with q and a; ex7: boxes with regional attributes (pA)."""
    def circle(N, R):
        i = np.arange(N)
        return np.stack([np.cos(i * 2 * np.pi / N), np.sin(i * 2 * np.pi / N)], axis=1) * R, np.stack([i, i + 1], axis=1) % N
    pts0, seg0 = circle(30, 1.4)
    pts1, seg1 = circle(16, 0.6)
    A = dict(vertices=np.vstack([pts0, pts1]), segments=np.vstack([seg0, seg1 + seg0.shape[0]]), holes=[[0, 0]])
    B = tr.triangulate(A, 'qpa0.05')
    verify('ex6', A, B, '--refined', '--min-angle', '20', '--max-area', '0.05')
    ring = polygon_area([tuple(p) for p in pts0.tolist()]) - polygon_area([tuple(p) for p in pts1.tolist()])
    check(math.isclose(areas(B).sum(), ring, rel_tol=1e-12), 'ex6: the triangles cover the ring, the hole empty (area %.12g)' % ring)
    tr.compare(plt, A, B)
    saved('ex6')
    vertices, segments, regions = [], [], []
    boxes = [(0, 0, 5, 5, 1), (1, 1, 3, 1, 2), (1, 3, 1, 1, 3), (3, 3, 1, 1, 4)]
    for x, y, w, h, attribute in boxes:
        i = len(vertices)
        vertices.extend([[x, y], [x + w, y], [x + w, y + h], [x, y + h]])
        segments.extend([(i, i + 1), (i + 1, i + 2), (i + 2, i + 3), (i + 3, i)])
        regions.append([x + 0.5 * w, y + 0.5 * h, attribute, 0])
    A = dict(vertices=vertices, segments=segments, regions=regions)
    B = tr.triangulate(A, 'pA')
    verify('ex7', A, B)
    centres = B['vertices'][B['triangles']].mean(axis=1)
    expected = [next(a for x, y, w, h, a in reversed(boxes) if x < cx < x + w and y < cy < y + h) for cx, cy in centres.tolist()]
    check(B['triangle_attributes'][:, 0].tolist() == expected, 'ex7: every triangle carries the attribute of the box it lies in')
    tr.compare(plt, A, B)
    saved('ex7')


def sample_examples():
    """The examples on get_data's samples: A, dots, spiral, face, box, la, bbox.1, face.1 and
    diamond_02_00009.1.v."""
    A = tr.get_data('A')
    check(len(A['vertices']) == 11 and len(A['segments']) == 11 and A['holes'].tolist() == [[2.0, 2.4]] and A['segments'].min() == 0,
          "get_data('A'): 11 vertices and segments numbered from 0, the hole")
    tr.plot(plt.axes(), **A)
    saved('PSLG')
    ax = tr.plot(None, labels=True, **tr.get_data('box'))
    check(sorted(t.get_text() for t in ax.texts) == sorted(str(k) for k in range(8)), 'plot(None, labels=True): new axes, the 8 vertices numbered')
    plt.close('all')
    for name, opts, extra in (('constrained_delaunay', 'p', []), ('conforming_delaunay', 'pq0D', ['--refined', '--delaunay']),
                              ('constrained_conforming_delaunay', 'pq30', ['--refined', '--min-angle', '30'])):
        t = tr.triangulate(A, opts)
        verify(name, A, t, *extra)
        tr.plot(plt.axes(), **t)
        saved(name)
    dots = tr.get_data('dots')
    d1 = tr.triangulate(dots)
    verify('delaunay', dots, d1, '--convex-hull', '--delaunay')
    tr.compare(plt, dots, d1)
    saved('delaunay')
    pts = dots['vertices']
    segs = tr.convex_hull(pts)
    hull_edges = set(map(frozenset, d1['triangles'][:, [0, 1]].tolist() + d1['triangles'][:, [1, 2]].tolist() + d1['triangles'][:, [2, 0]].tolist()))
    check(all(orient(pts[a], pts[b], p) >= 0 for a, b in segs.tolist() for p in pts) and len(segs) >= 3 and
          all(frozenset(s) in hull_edges for s in segs.tolist()), 'convex_hull(dots): every point on the left of every hull segment (exact)')
    tr.plot(plt.axes(), vertices=pts, segments=segs)
    saved('convex_hull')
    points, edges, ray_origin, ray_direct = tr.voronoi(pts)
    circumcentres = []
    for a, b, c in pts[d1['triangles']]:
        d = 2 * (a[0] * (b[1] - c[1]) + b[0] * (c[1] - a[1]) + c[0] * (a[1] - b[1]))
        circumcentres.append(sorted([((a @ a) * (b[1] - c[1]) + (b @ b) * (c[1] - a[1]) + (c @ c) * (a[1] - b[1])) / d,
                                     ((a @ a) * (c[0] - b[0]) + (b @ b) * (a[0] - c[0]) + (c @ c) * (b[0] - a[0])) / d]))
    far = max(min(np.abs(np.array(circumcentres) - np.sort(p)).max(axis=1).min() for p in points[k:k + 1]) for k in range(len(points)))
    check(len(points) == len(d1['triangles']) and far < 1e-9 and len(edges) + len(ray_origin) == (3 * len(d1['triangles']) + len(segs)) // 2,
          'voronoi(dots): one vertex per Delaunay triangle at its circumcentre (within %.1e), one edge or ray per Delaunay edge' % far)
    tr.compare(plt, dict(vertices=pts), dict(vertices=points, edges=edges, ray_origins=ray_origin, ray_directions=ray_direct))
    saved('voronoi')
    spiral = tr.get_data('spiral')
    for name, opts, extra in (('delaunay1', '', ['--delaunay']), ('quality_q', 'q', ['--refined', '--min-angle', '20']),
                              ('quality_q32.5', 'q32.5', ['--refined', '--min-angle', '32.5']), ('quality1', 'a.2', ['--refined', '--max-area', '0.2'])):
        t = tr.triangulate(spiral, opts) if opts else tr.triangulate(spiral)
        verify(name, spiral, t, *(extra if opts else extra + ['--convex-hull']))
        hull = hull_area(spiral['vertices'])
        check(math.isclose(areas(t).sum(), hull, rel_tol=1e-12), '%s: the triangles cover the hull (area %.12g)' % (name, hull))
        tr.compare(plt, spiral, t)
        saved(name)
    face = tr.get_data('face')
    for name, opts, extra in (('holes_cavities', 'p', []), ('constrained_conforming_delaunay1', 'pq10', ['--refined', '--min-angle', '10']),
                              ('conforming_delaunay1', 'pq0D', ['--refined'])):
        t = tr.triangulate(face, opts)
        verify(name, face, t, *extra)
        cavities = sum(polygon_area(l) for l in FACE_LOOPS)
        check(math.isclose(areas(t).sum(), polygon_area(FACE_OUTER) - cavities, rel_tol=1e-12), '%s: the face less its eyes and mouth' % name)
        tr.compare(plt, face, t)
        saved(name)
    box = tr.get_data('box')
    t = tr.triangulate(box, 'pc')
    verify('constrained_delaunay1', box, t, '--convex-hull')
    check(math.isclose(areas(t).sum(), 8.0, rel_tol=1e-12) and box['segment_markers'].tolist() == [[k] for k in range(2, 7)],
          "get_data('box') with markers; triangulate(box, 'pc'): the hull less the hole (area 8)")
    tr.compare(plt, box, t)
    saved('constrained_delaunay1')
    la_examples()
    refine_examples()
    face1 = tr.get_data('face.1')
    mine = tr.triangulate(face, 'p')
    check(all(np.array_equal(face1[k], mine[k]) for k in ('vertices', 'triangles', 'segments', 'holes')),
          "get_data('face.1') (the command line's files through loads) equals triangulate(face, 'p')")
    A, B = tr.triangulate(face1, 'rc'), tr.triangulate(face1, 'rpc')
    check(math.isclose(areas(A).sum(), areas(face1).sum(), rel_tol=1e-12) and math.isclose(areas(B).sum(), areas(face1).sum(), rel_tol=1e-12),
          "triangulate(face.1, 'rc') and 'rpc': the same area as face.1")
    bndry = lambda d: {k: d[k] for k in ('vertices', 'segments')}
    tr.compare(plt, bndry(A), bndry(B))
    saved('bndries')
    tr.plot(plt.axes(), **face1)
    saved('face')
    diamond = tr.get_data('diamond_02_00009')
    v = tr.get_data('diamond_02_00009.1.v')
    points, edges, origins, directions = tr.voronoi(diamond['vertices'])
    geometry = lambda p, e, o, d: (sorted(tuple(sorted(tuple(np.round(p[i], 12)) for i in r)) for r in e.tolist()),
                                   sorted((tuple(np.round(p[a], 12)), tuple(np.round(np.array(b) / np.hypot(*b), 12)))
                                          for a, b in zip(np.reshape(o, -1).tolist(), d.tolist())))
    check(geometry(points, edges, origins, directions) == geometry(v['vertices'], v['edges'], v['ray_origins'], v['ray_directions']),
          "voronoi(diamond) and get_data('diamond_02_00009.1.v') (the command line's -v files): the same edges and rays")
    tr.compare(plt, dict(vertices=diamond['vertices']), v)
    saved('voronoi1')


def layer(x, y):
    """Which of la's layers (0 top, 1 middle, 2 bottom) the point is in, from the polylines."""
    def below(line):
        return y < np.interp(x, [p[0] for p in line], [p[1] for p in line])
    return 2 if below(LA_LOW) else 1 if below(LA_TOP) else 0


def la_examples():
    la = tr.get_data('la')
    check(la['regions'].tolist() == [[5.0, -0.5, 0.0, 0.2], [5.0, -2.7, 0.0, 0.5], [5.0, -4.5, 0.0, 1.0]],
          "get_data('la'): a region line with one value is its area bound, attribute 0 (as the package reads la.poly)")
    plt.figure(figsize=(8, 7))
    ax1 = plt.subplot(311)
    tr.plot(ax1, **la)
    for k, opts in ((2, 'pq'), (3, 'pqa')):
        t = tr.triangulate(la, opts)
        verify('quality2_' + opts, la, t, '--refined', '--min-angle', '20')
        tr.plot(plt.subplot(310 + k, sharex=ax1, sharey=ax1), **t)
        if opts == 'pqa':
            centres = t['vertices'][t['triangles']].mean(axis=1)
            bound = np.array([LA_BOUNDS[layer(x, y)] for x, y in centres.tolist()])
            check((areas(t) <= bound).all() and math.isclose(areas(t).sum(), 50.0, rel_tol=1e-12),
                  "triangulate(la, 'pqa'): every triangle within its layer's bound (%d triangles)" % len(t['triangles']))
    saved('quality2')


def refine_examples():
    box1 = tr.get_data('bbox.1')
    check(len(box1['triangle_max_area']) == len(box1['triangles']), "get_data('bbox.1'): .node, .ele and .area")
    box2 = tr.triangulate(box1, 'rpa0.2')
    box3 = tr.triangulate(box2, 'rpa0.05')
    box4 = tr.triangulate(box3, 'rpa0.0125')
    total = areas(box1).sum()
    for name, m, bound in (('refine_0.2', box2, 0.2), ('refine_0.05', box3, 0.05), ('refine_0.0125', box4, 0.0125)):
        check(areas(m).max() <= bound and math.isclose(areas(m).sum(), total, rel_tol=1e-12),
              "%s: every triangle within %g, the area of bbox.1 kept (%d triangles)" % (name, bound, len(m['triangles'])))
    plt.figure(figsize=(15, 5))
    ax1 = plt.subplot(131, aspect='equal')
    tr.plot(ax1, **box2)
    tr.plot(plt.subplot(132, sharex=ax1, sharey=ax1), **box3)
    tr.plot(plt.subplot(133, sharex=ax1, sharey=ax1), **box4)
    saved('refine')
    # r with a bare a: each old triangle's own bound (-1: none), a0.5 besides for 'aa.5'.
    old = box1['vertices'][box1['triangles']]
    for name, opts, cap in (('refine1', 'rpa', math.inf), ('refine2', 'rpaa.5', 0.5)):
        m = tr.triangulate(box1, opts)
        wrong = 0
        for (cx, cy), area in zip(m['vertices'][m['triangles']].mean(axis=1).tolist(), areas(m).tolist()):
            k = next(k for k, (a, b, c) in enumerate(old.tolist())
                     if all(orient(p, q, (cx, cy)) >= 0 for p, q in ((a, b), (b, c), (c, a))))
            own = box1['triangle_max_area'][k, 0]
            wrong += area > min(own if own > 0 else math.inf, cap)
        check(wrong == 0, "triangulate(bbox.1, '%s'): every triangle within its old triangle's bound%s (%d triangles)" %
              (opts, ' and 0.5' if cap < math.inf else '', len(m['triangles'])))
        tr.plot(plt.axes(), **m)
        saved(name)


def errors():
    square = {'vertices': [[0, 0], [1, 0], [1, 1], [0, 1]]}
    for opts in ('pq70', 'pK', 'pa-1', 'pq30x'):
        try:
            tr.triangulate(square, opts)
            check(False, 'triangulate(square, %r): no error' % opts)
        except ValueError as e:
            check(True, 'triangulate(square, %r): ValueError (%s) "%s"' % (opts, type(e).__name__, e))
    for call, what in ((lambda: tr.get_data('no_such_sample'), "get_data('no_such_sample')"),
                       (lambda: tr.loads(node='3 2 0 0\n1 0 0\n2 1 0\n'), 'loads: a .node cut short'),
                       (lambda: tr.loads(poly='3 2 0 0\n1 0 0\n2 1 x\n3 0 1\n0 0\n0\n'), 'loads: a word that is no number')):
        try:
            call()
            check(False, '%s: no error' % what)
        except ValueError as e:
            check('no_such_sample' in str(e) or 'line' in str(e) or 'ends' in str(e), '%s: ValueError "%s"' % (what, e))
    # Without matplotlib: an ImportError that names the package to install.
    code = ('import sys; sys.modules["matplotlib"] = None; sys.modules["matplotlib.pyplot"] = None\n'
            'import deltri\ntry:\n    deltri.plot(None, vertices=[[0, 0]])\nexcept ImportError as e:\n    print(e)\n')
    run = subprocess.run([sys.executable, '-c', code], capture_output=True, text=True)
    check('python3-matplotlib' in run.stdout, 'plot without matplotlib: ImportError "%s"' % run.stdout.strip())


def main():
    try:
        make_samples()
        os.environ['DELTRI_TRIANGLE_DATA'] = DATA
        api_page()
        point_examples()
        hole_and_region_examples()
        sample_examples()
        errors()
    finally:
        shutil.rmtree(WORK)
    finish()


main()
