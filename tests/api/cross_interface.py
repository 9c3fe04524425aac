"""The same input through the command line, the C library, the C++ library and the Python module
must give the same mesh or the same class of error (issue 47: a long option in the library's
switch string made the C library and the module take the input for a refinement and drop its
holes and regions, status OK).
    cross_interface.py DELTRI C_CLIENT CPP_CLIENT
The input is a 3x3 square with a 1x1 hole (and, for some cases, a region point with attribute 7
and area bound 0.05). For each switch string, long options included:
  * deltri -z<letters> <options> square.poly, the C client (tests/api/cross_client.c, through
    deltri_triangulate), the C++ client (cross_client.cpp, deltri::triangulate) and
    deltri.triangulate give the same points bit for bit, the same triangles, triangle attributes
    and segments, numbered from 0;
  * independent facts, computed here from the triangles: the areas sum to 8 (the hole is carved),
    no triangle lies in the hole, no angle is below the -q bound, and with a region: every
    triangle has its attribute and no area above its bound;
  * a bad input or switch string (a NaN hole or region point, a vertex at infinity, q70,
    --threads=0, an unknown option) is an input error (exit status 1, DELTRI_INPUT_ERROR, DeltriError with code 1)
    or a switch error (2) in every interface alike."""
import math
import os
import shutil
import subprocess
import sys
import tempfile

import numpy as np

import deltri
from apitest import check, finish, read_output, write_poly

POINTS = [[0, 0], [3, 0], [3, 3], [0, 3], [1, 1], [2, 1], [2, 2], [1, 2]]
SEGMENTS = [[0, 1], [1, 2], [2, 3], [3, 0], [4, 5], [5, 6], [6, 7], [7, 4]]
HOLE = [[1.5, 1.5]]
REGION = [[0.5, 0.5, 7, 0.05]]

# name, switch string (no z: it is added for every interface), input changes, expected outcome:
# 'mesh' or the error status (1 input, 2 switches; the command line's exit status is the same number).
CASES = [
    ('plain', 'pq30', {}, 'mesh'),
    ('threads', 'pq30 --threads=2', {}, 'mesh'),
    ('ruppert', 'pq30 --algorithm=ruppert', {}, 'mesh'),
    ('range-restricted', 'pq30 --range-restricted', {}, 'mesh'),
    ('corner-lopping', 'pq30 --corner-lopping', {}, 'mesh'),
    ('chew, interior bound', 'pq30 --algorithm=chew --interior-bound=1', {}, 'mesh'),
    ('region, threads', 'pq30aA --threads=2', {'regions': REGION}, 'mesh'),
    ('region, range-restricted', 'pq30aA --range-restricted', {'regions': REGION}, 'mesh'),
    ('region, smooth', 'pq30aA --smooth=2', {'regions': REGION}, 'mesh'),
    ('smooth=0', 'pq30 --smooth=0', {}, 2),
    ('NaN hole, threads', 'pq30 --threads=2', {'holes': [[float('nan'), 1.5]]}, 1),
    ('NaN region, ruppert', 'pq30A --algorithm=ruppert', {'regions': [[0.5, float('nan'), 7, 0]]}, 1),
    ('infinite vertex', 'pq30 --range-restricted', {'vertices': POINTS[:2] + [[float('inf'), 3]] + POINTS[3:]}, 1),
    ('q70', 'pq70 --threads=2', {}, 2),
    ('threads=0', 'pq30 --threads=0', {}, 2),
    ('unknown option', 'pq30 --no-such-option', {}, 2),
]

def write_flat(path, d):
    with open(path, 'w') as f:
        for name, key in (('points', 'vertices'), ('segments', 'segments'), ('holes', 'holes'), ('regions', 'regions')):
            rows = d.get(key, [])
            if rows:
                f.write('%s %d %d\n' % (name, len(rows), len(rows[0])))
                for r in rows:
                    f.write(' '.join(repr(float(x)) for x in r) + '\n')


def mesh(points, triangles, attributes, segments):
    return {'points': np.array(points, dtype=np.float64).reshape(-1, 2),
            'triangles': np.array(triangles, dtype=np.int64).reshape(-1, 3),
            'attributes': np.array(attributes, dtype=np.float64).reshape(len(triangles), -1) if len(triangles) else
                          np.zeros((0, 0)),
            'segments': np.array(segments, dtype=np.int64).reshape(-1, 2)}


def from_cli(deltri_path, d, switches, work):
    for name in os.listdir(work):
        os.remove(os.path.join(work, name))
    write_poly(os.path.join(work, 'square.poly'), d)
    words = switches.split()
    run = subprocess.run([deltri_path, '-z' + words[0]] + words[1:] + ['square.poly'], cwd=work,
                         capture_output=True, text=True)
    if run.returncode != 0:
        return ('status', run.returncode, run.stderr.strip())
    m = read_output(os.path.join(work, 'square.1'))
    t = m['triangles']
    return mesh(m['vertices'], t, m.get('triangle_attributes', np.zeros((len(t), 0))), m['segments'])


def from_client(client, d, switches, work):
    flat = os.path.join(work, 'input.flat')
    write_flat(flat, d)
    run = subprocess.run([client, 'z' + switches, flat], capture_output=True, text=True)
    if run.returncode != 0:
        return ('client failed', run.returncode, run.stderr.strip())
    text = run.stdout
    if text.startswith('status '):
        code, message = text[7:].rstrip('\n').split(' ', 1)
        return ('status', int(code), message)
    L = [l.split() for l in text.splitlines()]
    n = int(L[0][1])
    points = [[float(x) for x in l] for l in L[1:1 + n]]
    k = 1 + n
    t, c, na = (int(x) for x in L[k][1:4])
    rows = L[k + 1:k + 1 + t]
    k += 1 + t
    s = int(L[k][1])
    return mesh(points, [[int(x) for x in r[:3]] for r in rows], [[float(x) for x in r[c:c + na]] for r in rows],
                [[int(x) for x in l] for l in L[k + 1:k + 1 + s]])


def from_python(d, switches):
    try:
        m = deltri.triangulate(d, switches)
    except deltri.DeltriError as e:
        return ('status', e.code, str(e))
    t = m['triangles']
    return mesh(m['vertices'], t, m.get('triangle_attributes', np.zeros((len(t), 0))), m.get('segments', []))


def facts(m, region, min_angle):
    """What must hold of a mesh of the square with its hole, from its triangles alone."""
    p = m['points'][m['triangles']]
    a = 0.5 * ((p[:, 1, 0] - p[:, 0, 0]) * (p[:, 2, 1] - p[:, 0, 1]) - (p[:, 1, 1] - p[:, 0, 1]) * (p[:, 2, 0] - p[:, 0, 0]))
    centroid = p.mean(axis=1)
    in_hole = (centroid[:, 0] > 1) & (centroid[:, 0] < 2) & (centroid[:, 1] > 1) & (centroid[:, 1] < 2)
    worst = 180.0
    for tri in p:
        for k in range(3):
            u, v = tri[(k + 1) % 3] - tri[k], tri[(k + 2) % 3] - tri[k]
            cos = np.dot(u, v) / (np.linalg.norm(u) * np.linalg.norm(v))
            worst = min(worst, math.degrees(math.acos(max(-1.0, min(1.0, cos)))))
    out = ['total area %.15g (8 expected)' % a.sum() if abs(a.sum() - 8) > 1e-12 else None,
           '%d triangles in the hole' % in_hole.sum() if in_hole.any() else None,
           'smallest angle %.6g below %g' % (worst, min_angle) if worst < min_angle - 1e-9 else None,
           'a triangle not counter-clockwise' if (a <= 0).any() else None]
    if region:
        attribute = m['attributes'][:, 0] if m['attributes'].shape[1] else np.zeros(len(a))
        out.append('attributes %s, not all 7' % sorted(set(attribute.tolist()))[:4] if (attribute != 7).any() else None)
        out.append('largest area %.4g above the region bound 0.05' % a.max() if a.max() > 0.05 else None)
    return [x for x in out if x]


def same(a, b):
    return all(a[k].shape == b[k].shape and np.array_equal(a[k], b[k]) for k in ('points', 'triangles', 'attributes', 'segments'))


def main():
    deltri_path, c_client, cpp_client = sys.argv[1:4]
    work = tempfile.mkdtemp()
    try:
        for name, switches, changes, expected in CASES:
            d = dict({'vertices': POINTS, 'segments': SEGMENTS, 'holes': HOLE}, **changes)
            got = {'command line': from_cli(deltri_path, d, switches, work),
                   'C': from_client(c_client, d, switches, work),
                   'C++': from_client(cpp_client, d, switches, work),
                   'Python': from_python(d, switches)}
            label = '%s (%s)' % (name, switches)
            for interface, result in got.items():
                if isinstance(result, tuple):
                    what = 'error %d: %s' % (result[1], result[2]) if result[0] == 'status' else '%s %d: %s' % result
                    check(result[0] == 'status' and result[1] == expected,
                          '%s, %s: %s%s' % (label, interface, what, '' if expected != 'mesh' else ' (a mesh expected)'))
                elif expected != 'mesh':
                    check(False, '%s, %s: a mesh of %d triangles, error %d expected' %
                          (label, interface, len(result['triangles']), expected))
                else:
                    wrong = facts(result, 'regions' in changes, 30)  # every mesh case asks q30
                    check(not wrong, '%s, %s: %d triangles%s' % (label, interface, len(result['triangles']),
                                                                 ': ' + '; '.join(wrong) if wrong else ', area 8, the hole carved'))
            meshes = {k: v for k, v in got.items() if not isinstance(v, tuple)}
            if expected == 'mesh' and len(meshes) == len(got):
                check(all(same(meshes['command line'], m) for m in meshes.values()),
                      '%s: the four interfaces give the same mesh' % label)
    finally:
        shutil.rmtree(work)
    finish()


main()
