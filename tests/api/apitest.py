"""What the Python tests of tests/api share: the ok/FAIL lines and their count, Triangle's files read
as rows of words, the command line's output files read as the `triangle` package's dict (numbered
from 0), and a dict written as files for the independent checkers."""
import os
import sys

import numpy as np

failures = []


def check(condition, what):
    print(('ok   ' if condition else 'FAIL ') + what)
    if not condition:
        failures.append(what)


def finish():
    """Exits 1 after saying how many checks failed, if any did."""
    if failures:
        print('%d failures' % len(failures))
        sys.exit(1)


def lines(path):
    return [l for l in (raw.split('#')[0].split() for raw in open(path)) if l]


def read_output(stem):
    """The command line's STEM.node, .ele and .poly (and .edge, .neigh when there), numbered from 0
    whatever the files' first number is (as in Triangle, the input's first index numbers them)."""
    node, ele = lines(stem + '.node'), lines(stem + '.ele')
    n, _, na, nm = (int(x) for x in node[0][:4])
    f0 = int(node[1][0])

    def ix(x):
        return int(x) - f0 if int(x) >= 0 else int(x)
    t, c, ta = (int(x) for x in ele[0][:3])
    out = {'vertices': np.array([[float(f[1]), float(f[2])] for f in node[1:1 + n]]),
           'triangles': np.array([[ix(x) for x in f[1:1 + c]] for f in ele[1:1 + t]]).reshape(-1, c)}
    if na:
        out['vertex_attributes'] = np.array([[float(x) for x in f[3:3 + na]] for f in node[1:1 + n]])
    if nm:
        out['vertex_markers'] = np.array([[int(f[3 + na])] for f in node[1:1 + n]])
    if ta:
        out['triangle_attributes'] = np.array([[float(x) for x in f[1 + c:1 + c + ta]] for f in ele[1:1 + t]])
    if os.path.exists(stem + '.poly'):
        poly = lines(stem + '.poly')
        ns = int(poly[1][0])
        out['segments'] = np.array([[ix(f[1]), ix(f[2])] for f in poly[2:2 + ns]]).reshape(-1, 2)
        if int((poly[1] + ['0'])[1]):
            out['segment_markers'] = np.array([[int(f[3])] for f in poly[2:2 + ns]])
    if os.path.exists(stem + '.edge'):
        edge = lines(stem + '.edge')
        out['edges'] = np.array([[ix(f[1]), ix(f[2])] for f in edge[1:]])
        if int((edge[0] + ['0'])[1]):
            out['edge_markers'] = np.array([[int(f[3])] for f in edge[1:]])
    if os.path.exists(stem + '.neigh'):
        out['neighbors'] = np.array([[ix(x) for x in f[1:4]] for f in lines(stem + '.neigh')[1:]])
    return out


def write_poly(path, d):
    """d (vertices, and segments, holes, regions where it has them) as one .poly, numbered from 0,
    coordinates exact (repr): the input as the command line and the checkers read it."""
    with open(path, 'w') as f:
        f.write('%d 2 0 0\n' % len(d['vertices']))
        for k, (x, y) in enumerate(d['vertices']):
            f.write('%d %r %r\n' % (k, float(x), float(y)))
        f.write('%d 0\n' % len(d.get('segments', [])))
        for k, (a, b) in enumerate(d.get('segments', [])):
            f.write('%d %d %d\n' % (k, a, b))
        f.write('%d\n' % len(d.get('holes', [])))
        for k, (x, y) in enumerate(d.get('holes', [])):
            f.write('%d %r %r\n' % (k, float(x), float(y)))
        f.write('%d\n' % len(d.get('regions', [])))
        for k, r in enumerate(d.get('regions', [])):
            f.write('%d %s\n' % (k, ' '.join(repr(float(x)) for x in r)))


def write_files(stem, d):
    """d's vertices (and triangles, segments, holes, regions where it has them) as STEM.node,
    STEM.ele and, where d has segments, STEM.poly, numbered from 0, coordinates exact (repr)."""
    v = np.asarray(d['vertices'], dtype=np.float64).reshape(-1, 2)
    rows = ['%d 2 0 0' % len(v)] + ['%d %r %r' % (k, x, y) for k, (x, y) in enumerate(v.tolist())]
    with open(stem + '.node', 'w') as f:
        f.write('\n'.join(rows) + '\n')
    if 'triangles' in d:
        t = np.asarray(d['triangles'])[:, :3]
        with open(stem + '.ele', 'w') as f:
            f.write('%d 3 0\n' % len(t) + ''.join('%d %d %d %d\n' % (k, a, b, c) for k, (a, b, c) in enumerate(t.tolist())))
    if 'segments' not in d:
        return
    s = np.asarray(d['segments'], dtype=np.int64).reshape(-1, 2)
    h = np.asarray(d.get('holes', np.zeros((0, 2))), dtype=np.float64).reshape(-1, 2)
    r = np.asarray(d.get('regions', np.zeros((0, 4))), dtype=np.float64).reshape(-1, 4)
    with open(stem + '.poly', 'w') as f:
        f.write('0 2 0 0\n%d 0\n' % len(s) + ''.join('%d %d %d\n' % (k, a, b) for k, (a, b) in enumerate(s.tolist())))
        f.write('%d\n' % len(h) + ''.join('%d %r %r\n' % (k, x, y) for k, (x, y) in enumerate(h.tolist())))
        f.write('%d\n' % len(r) + ''.join('%d %s\n' % (k, ' '.join(repr(x) for x in row)) for k, row in enumerate(r.tolist())))
