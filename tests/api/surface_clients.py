"""The library's facets in 3-D (deltri_mesh_surface, deltri::mesh_surface, deltri.mesh_surface)
against the command line and against independent facts.
    surface_clients.py DELTRI C_CLIENT CPP_CLIENT SOURCE_DIR
For the cube, the L-bracket with a through-hole, the T (three facets at one segment), the house
(point markers, a window cut through a facet, a segment inside a facet) and a real TetGen surface
whose points are in a separate .node (tests/surface/inputs), each with one or more switch strings:
  * the C client (tests/api/surface_client.c), the C++ client (surface_client.cpp) and the Python
    module give the same arrays as the command line's .node, .ele and .edge for the same switches
    (points bit for bit, numbering shifted only by the 0/1 first index);
  * independent checks of the arrays from the input facets alone (numpy, the facet reading of
    tests/surface/check_surface.py): the input points first and unchanged; every triangle within
    1e-9 of its facet's size from that facet's least-squares plane and carrying its marker; per
    facet the triangles' areas summing to the polygon area to 1e-9; every edge in exactly two
    triangles on the closed inputs (watertight), and on the T the edges along the shared segment in
    three; no angle below the -q bound; no area above the -a bound.
Then the bad inputs (a facet not planar, a corner out of range, a facet with no polygons): every
client gets the input-error status with a message naming the facet (for the non-planar one, its
distance from the best plane, the same text as the command line's after file:line), and no output
(the C client checks that its struct was left untouched; C++ and Python raise)."""
import math
import os
import shutil
import subprocess
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'surface'))
import check_surface as facts  # noqa: E402  (its facet reader, planes and polygon areas)

import deltri  # noqa: E402

CASES = [  # input, closed, switch strings (without the dash)
    ('cube.smesh', True, ['pq30', 'pq30a0.02', 'pzq20']),
    ('l_bracket.poly', True, ['pq30', 'pq30a0.05', 'pBq25']),
    ('tee.poly', False, ['pq30', 'pq30a0.01', 'pzq30a0.05']),
    ('house.poly', False, ['pq30', 'pq30a0.02']),
    ('pynastran_sphere.smesh', True, ['pq30a0.05']),
]
failures = []


def fail(msg):
    failures.append(msg)
    print('FAIL:', msg)


def read_input(path):
    """The facets (0-based corners), the file's first index and its point markers (or None)."""
    pts, facets = facts.read_facets(path)
    lines = facts.data_lines(path)
    head = next(lines)
    if int(head[0]) == 0:  # TetGen's layout: the points are in <base>.node
        lines = facts.data_lines(facts.companion_node(path))
        head = next(lines)
    rows = [next(lines) for _ in range(int(head[0]))]
    markers = [int(r[4 + (int(head[2]) if len(head) > 2 else 0)]) for r in rows] \
        if len(head) > 3 and int(head[3]) else None
    return pts, facets, int(rows[0][0]), markers


def write_flat(path, pts, facets, markers, first):
    with open(path, 'w') as f:
        f.write('%d %d\n' % (len(pts), markers is not None))
        for k, p in enumerate(pts):
            f.write('%r %r %r%s\n' % (float(p[0]), float(p[1]), float(p[2]),
                                      ' %d' % markers[k] if markers is not None else ''))
        f.write('%d\n' % len(facets))
        for m, polys, holes in facets:
            f.write('%d %d %d\n' % (len(polys), len(holes), m))
            for q in polys:
                f.write('%d %s\n' % (len(q), ' '.join(str(v + first) for v in q)))
            for h in holes:
                f.write('%r %r %r\n' % tuple(float(x) for x in h))


def parse_client(text, first):
    """The client's printout as arrays numbered from 0, or ('status', code, message)."""
    if text.startswith('status '):
        code, message = text[7:].rstrip('\n').split(' ', 1)
        return ('status', int(code), message)
    lines = [l.split() for l in text.splitlines()]
    r, k = {}, 0
    n, mk = int(lines[0][1]), int(lines[0][2])
    P = lines[1:1 + n]
    r['vertices'] = np.array([[float(x) for x in l[:3]] for l in P])
    if mk:
        r['vertex_markers'] = np.array([int(l[3]) for l in P])
    k = 1 + n
    t = int(lines[k][1])
    T = lines[k + 1:k + 1 + t]
    r['triangles'] = np.array([[int(x) - first for x in l[:3]] for l in T]).reshape(-1, 3)
    r['triangle_attributes'] = np.array([float(l[3]) for l in T])
    r['triangle_facets'] = np.array([int(l[4]) - first for l in T])
    k += 1 + t
    e, mk = int(lines[k][1]), int(lines[k][2])
    E = lines[k + 1:k + 1 + e]
    r['edges'] = np.array([[int(x) - first for x in l[:2]] for l in E]).reshape(-1, 2)
    if mk:
        r['edge_markers'] = np.array([int(l[2]) for l in E])
    return r


def from_python(res):
    r = {k: np.asarray(v) for k, v in res.items()}
    for key in ('vertex_markers', 'triangle_attributes', 'edge_markers'):
        if key in r:
            r[key] = r[key].reshape(-1)
    return r


def read_cli(stem, first):
    """The command line's .node, .ele and .edge, numbered from 0."""
    r = {}
    head, rows = facts.read_table(stem + '.node', 4)
    r['vertices'] = np.array([[float(x) for x in l[1:4]] for l in rows])
    if int(head[3]):
        r['vertex_markers'] = np.array([int(l[4]) for l in rows])
    _, rows = facts.read_table(stem + '.ele', 4)
    r['triangles'] = np.array([[int(x) - first for x in l[1:4]] for l in rows]).reshape(-1, 3)
    r['triangle_attributes'] = np.array([float(l[4]) for l in rows])
    head, rows = facts.read_table(stem + '.edge', 3)
    r['edges'] = np.array([[int(x) - first for x in l[1:3]] for l in rows]).reshape(-1, 2)
    if int(head[1]):
        r['edge_markers'] = np.array([int(l[3]) for l in rows])
    return r


def same(tag, got, want):
    # The report items (merged points, emptied facets, a budget's stop) have no file of their own:
    # tests/api/surface_report.py checks them.
    report = {'triangle_facets', 'merged_vertices', 'emptied_facets', 'budget_reached', 'rounds_exhausted',
              'triangles_below_angle', 'triangles_above_area'}
    keys = sorted(set(want) | (set(got) - report))
    for key in keys:
        if key not in got or key not in want:
            fail('%s: %s only in %s' % (tag, key, 'the library' if key in got else 'the command line'))
        elif got[key].shape != want[key].shape or not np.array_equal(got[key], want[key]):
            fail('%s: %s differ (%s vs %s)' % (tag, key, got[key].shape, want[key].shape))


def check_facts(tag, r, pts, facets, closed, q, amax):
    P, T, F = r['vertices'], r['triangles'], r['triangle_facets']
    if not (len(F) == len(T) == len(r['triangle_attributes'])) or T.min() < 0 or T.max() >= len(P):
        fail('%s: triangles, their facets and attributes disagree, or a corner is not a point' % tag)
        return len(T), 0.0
    if not np.array_equal(P[:len(pts)], pts):
        fail('%s: the input points are not the first points, unchanged' % tag)
    A, B, C = P[T[:, 0]], P[T[:, 1]], P[T[:, 2]]
    areas = 0.5 * np.linalg.norm(np.cross(B - A, C - A), axis=1)
    for f, (m, polys, holes) in enumerate(facets):
        mine = F == f
        if not mine.any():
            fail('%s: facet %d has no triangles' % (tag, f))
            continue
        c, u, v, n = facts.frame(pts, polys)
        size = np.ptp(pts[[i for p in polys for i in p]], axis=0).max()
        off = max(np.abs((X[mine] - c) @ n).max() for X in (A, B, C))
        if off > 1e-9 * size:
            fail('%s: facet %d: a triangle corner lies %.3g from its plane' % (tag, f, off))
        if not np.all(r['triangle_attributes'][mine] == m):
            fail('%s: facet %d: triangles without its marker %d' % (tag, f, m))
        want = facts.facet_area(pts, polys, holes, (c, u, v, n))
        if abs(areas[mine].sum() - want) > 1e-9 * want:
            fail('%s: facet %d: triangle areas sum to %.15g, the facet has %.15g' % (tag, f, areas[mine].sum(), want))
    count = {}
    for t in T:
        for i in range(3):
            e = (min(t[i], t[i - 1]), max(t[i], t[i - 1]))
            count[e] = count.get(e, 0) + 1
    if closed:
        bad = [e for e, k in count.items() if k != 2]
        if bad:
            fail('%s: not watertight: %d edges not in exactly two triangles, e.g. %s' % (tag, len(bad), bad[0]))
    if tag.startswith('tee'):  # the segment from point 0 to point 3 is held by all three facets
        on = [k for e, k in count.items() if shared_segment(P[list(e)])]
        if not on or any(k != 3 for k in on):
            fail('%s: edges along the shared segment are in %s triangles, not 3 each' % (tag, sorted(set(on))))
    smallest = 180.0
    for X, Y, Z in ((A, B, C), (B, C, A), (C, A, B)):
        a, b = Y - X, Z - X
        ang = np.degrees(np.arctan2(np.linalg.norm(np.cross(a, b), axis=1), np.einsum('ij,ij->i', a, b)))
        smallest = min(smallest, ang.min())
    if smallest < q - 1e-9:
        fail('%s: smallest angle %.4f below %g' % (tag, smallest, q))
    if amax and areas.max() > amax * (1 + 1e-9):
        fail('%s: largest area %.6g above %g' % (tag, areas.max(), amax))
    return len(T), smallest


def shared_segment(ends):
    """Both ends on the T's shared segment x = y = 0, 0 <= z <= 1."""
    return bool(np.all(ends[:, 0] == 0) and np.all(ends[:, 1] == 0))


def switch_numbers(sw):
    q = float(sw.split('q')[1].split('a')[0]) if 'q' in sw else 0.0
    amax = float(sw.split('a')[1]) if 'a' in sw else None
    return q, amax


def run_client(client, switches, flat):
    r = subprocess.run([client, switches, flat], capture_output=True, text=True)
    if r.returncode != 0 or r.stderr:
        fail('%s %s: exit %d, stderr %r' % (os.path.basename(client), switches, r.returncode, r.stderr))
        return None
    return r.stdout


def meshes(c_client, cpp_client, sw, pts, facets, markers, flat_dir, name):
    """The three libraries' results for the switch string sw, numbered from 0."""
    first = 0 if 'z' in sw else 1
    flat = os.path.join(flat_dir, name + '.' + sw + '.flat')
    write_flat(flat, pts, facets, markers, first)
    d = {'vertices': pts, 'facets': [{'polygons': p, 'holes': h, 'marker': m} for m, p, h in facets]}
    if markers is not None:
        d['vertex_markers'] = markers
    out = {}
    for lang, client in (('C', c_client), ('C++', cpp_client)):
        text = run_client(client, sw, flat)
        if text is not None:
            out[lang] = parse_client(text, first)
    try:
        out['Python'] = from_python(deltri.mesh_surface(d, sw.replace('z', '')))
    except deltri.DeltriError as e:
        out['Python'] = ('status', e.code, str(e))
    return out


def check_case(deltri_cli, c_client, cpp_client, src, work, name, closed, sw):
    path = os.path.join(src, 'tests', 'surface', 'inputs', name)
    pts, facets, file_first, markers = read_input(path)
    shutil.copy(path, work)
    if os.path.exists(facts.companion_node(path)):
        shutil.copy(facts.companion_node(path), work)
    run = subprocess.run([deltri_cli, '-Q' + sw, name], cwd=work, capture_output=True, text=True)
    if run.returncode != 0:
        fail('%s -%s: the command line failed: %s' % (name, sw, run.stderr.strip()))
        return
    cli = read_cli(os.path.join(work, name.rsplit('.', 1)[0] + '.1'), 0 if 'z' in sw else file_first)
    q, amax = switch_numbers(sw)
    tag = '%s -%s' % (name, sw)
    results = meshes(c_client, cpp_client, sw, pts, facets, markers, work, name)
    for lang, r in results.items():
        if isinstance(r, tuple):
            fail('%s: %s: %s' % (tag, lang, r))
            continue
        same(tag + ' ' + lang, r, cli)
    if 'Python' in results and not isinstance(results['Python'], tuple):
        n, smallest = check_facts(tag, results['Python'], pts, facets, closed, q, amax)
        print('ok %-30s %5d triangles, smallest angle %.2f; C, C++, Python equal to the files' % (tag, n, smallest))


def check_bad(deltri_cli, c_client, cpp_client, src, work):
    inputs = os.path.join(src, 'tests', 'surface', 'inputs')
    pts, facets, _, _ = read_input(os.path.join(inputs, 'nonplanar.poly'))
    shutil.copy(os.path.join(inputs, 'nonplanar.poly'), work)
    cli = subprocess.run([deltri_cli, '-pq30', 'nonplanar.poly'], cwd=work, capture_output=True, text=True).stderr.strip()
    cli_text = cli[cli.index('facet '):] if 'facet ' in cli else '(the command line said %r)' % cli
    cube, cube_facets, _, _ = read_input(os.path.join(inputs, 'cube.smesh'))
    out_of_range = [list(f) for f in cube_facets]
    out_of_range[1] = (out_of_range[1][0], [[2, 3, 98, 6]], [])   # 0-based 98: corner 99 from 1
    empty = [list(f) for f in cube_facets]
    empty[2] = (empty[2][0], [], [])
    cases = [('nonplanar', pts, facets, [cli_text, 'from the best plane']),
             ('corner out of range', cube, out_of_range, ['facet 2: corner 99 is not a point (points are numbered 1 to 8)']),
             ('empty facet', cube, empty, ['facet 3: it has no polygons'])]
    for what, p, f, wants in cases:
        results = meshes(c_client, cpp_client, 'pq30', p, f, None, work, what.replace(' ', '_'))
        if what == 'corner out of range':  # the Python module numbers from 0
            wants_py = ['facet 1: corner 98 is not a point (points are numbered 0 to 7)']
        elif what == 'empty facet':
            wants_py = ['facet 2: it has no polygons']
        else:
            wants_py = [cli_text.replace('facet 1:', 'facet 0:'), 'from the best plane']
        for lang, r in results.items():
            want = wants_py if lang == 'Python' else wants
            if not isinstance(r, tuple) or r[1] != 1 or not all(w in r[2] for w in want):
                got = r if isinstance(r, tuple) else 'a mesh'
                fail('%s: %s gave %s, expected status 1 with %r' % (what, lang, got, want))
            else:
                print('ok %-20s %-6s status %d: %s' % (what, lang, r[1], r[2]))


def main():
    deltri_cli, c_client, cpp_client, src = sys.argv[1:5]
    with tempfile.TemporaryDirectory() as work:
        for name, closed, switches in CASES:
            for sw in switches:
                check_case(deltri_cli, c_client, cpp_client, src, work, name, closed, sw)
        check_bad(deltri_cli, c_client, cpp_client, src, work)
    print('%d failures' % len(failures))
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())
