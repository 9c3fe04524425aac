"""The Python module (src/api/python/deltri) on the shared library of this build:
the dict round trip against the command line's files, the size callback meshing finer where it
asks, and exceptions on bad input.
    DELTRI_LIBRARY=.../libdeltri.so.0 PYTHONPATH=src/api/python test_python.py DELTRI SOURCE_DIR"""
import math
import os
import shutil
import subprocess
import sys
import tempfile

import numpy as np

import deltri
from apitest import check, finish, lines, read_output

def read_poly(path):
    """A .poly as the `triangle` package's dict (numbered from 0)."""
    L = lines(path)
    n, _, na, nm = (int(x) for x in L[0][:4])
    first = int(L[1][0])
    v = L[1:1 + n]
    d = {'vertices': [[float(f[1]), float(f[2])] for f in v]}
    if na:
        d['vertex_attributes'] = [[float(x) for x in f[3:3 + na]] for f in v]
    if nm:
        d['vertex_markers'] = [[int(f[3 + na])] for f in v]
    k = 1 + n
    ns, sm = (int(x) for x in (L[k] + ['0'])[:2])
    s = L[k + 1:k + 1 + ns]
    d['segments'] = [[int(f[1]) - first, int(f[2]) - first] for f in s]
    if sm:
        d['segment_markers'] = [[int(f[3])] for f in s]
    k += 1 + ns
    nh = int(L[k][0])
    if nh:
        d['holes'] = [[float(f[1]), float(f[2])] for f in L[k + 1:k + 1 + nh]]
    k += 1 + nh
    if k < len(L) and int(L[k][0]):
        d['regions'] = [[float(x) for x in f[1:5]] for f in L[k + 1:k + 1 + int(L[k][0])]]
    return d


def cli(deltri_path, source, switches, work):
    shutil.copy(source, work)
    name = os.path.basename(source)
    subprocess.run([deltri_path, '-' + switches, name], cwd=work, check=True, capture_output=True)
    return read_output(os.path.join(work, name.rsplit('.', 1)[0] + '.1'))


def areas(m):
    p = m['vertices'][m['triangles'][:, :3]]
    return 0.5 * ((p[:, 1, 0] - p[:, 0, 0]) * (p[:, 2, 1] - p[:, 0, 1]) - (p[:, 1, 1] - p[:, 0, 1]) * (p[:, 2, 0] - p[:, 0, 0]))


def expect_error(d, opts, words, what, code=1):
    """deltri.triangulate(d, opts) must raise DeltriError (a ValueError) with `code` and every word."""
    try:
        m = deltri.triangulate(d, opts)
        check(False, '%s: no error, %d triangles' % (what, len(m.get('triangles', []))))
    except deltri.DeltriError as e:
        check(isinstance(e, ValueError) and e.code == code and all(w in str(e) for w in words),
              '%s: DeltriError %d "%s"' % (what, e.code, e))
    except Exception as e:  # noqa: BLE001  (numpy's or ctypes' own error: the key is not named)
        check(False, '%s: %s "%s", not DeltriError' % (what, type(e).__name__, e))


def arrays(square):
    """Issue 47 items 2, 3 and 12: every array's length, shape, type and range checked against its
    items, with an error naming the key; nothing read past an array's end or reinterpreted."""
    check(issubclass(deltri.DeltriError, ValueError), 'DeltriError is a ValueError, as the triangle package raises')
    # Optional arrays shorter than their items (they were read past their end: garbage, then SIGSEGV).
    n = 3000
    ring = [[math.cos(2 * math.pi * k / n), math.sin(2 * math.pi * k / n)] for k in range(n)]
    expect_error({'vertices': ring, 'vertex_markers': [1]}, 'Q', ['vertex_markers', '1 value for 3000 vertices', 'expected 3000'],
                 'vertex_markers of 1 for 3000 vertices')
    expect_error({'vertices': ring, 'vertex_attributes': [[1.0, 2.0]]}, 'Q', ['vertex_attributes', '1 row for 3000 vertices', 'expected 3000'],
                 'vertex_attributes of 1 row for 3000 vertices')
    expect_error(dict(square, segment_markers=[5, 6]), 'p', ['segment_markers', '2 values', '4 segments', 'expected 4'],
                 'segment_markers of 2 for 4 segments')
    first = deltri.triangulate(square, 'pq30a0.01')
    t = len(first['triangles'])
    expect_error(dict(first, triangle_max_area=[0.1]), 'rpa', ['triangle_max_area', '1 value for %d triangles' % t, 'expected %d' % t],
                 'triangle_max_area of 1 for %d triangles' % t)
    expect_error(dict(first, triangle_attributes=[[1.0]] * (t - 1)), 'rpA', ['triangle_attributes', '%d values for %d triangles' % (t - 1, t)],
                 'triangle_attributes of %d for %d triangles' % (t - 1, t))
    expect_error(dict(square, segment_markers=[1, 2, 3, 4], segments=None), 'p', ['segment_markers', 'expected 0'],
                 'segment_markers without segments')
    # Shapes: a (4, 3) segment array is not 6 segments, a 4 x 3 region array not 3 regions.
    expect_error(dict(square, segments=np.array([[0, 1, 2], [1, 2, 3], [2, 3, 0], [3, 0, 1]])), 'p', ['segments', '(4, 3)', '(n, 2)'],
                 'segments of shape (4, 3)')
    expect_error(dict(square, regions=np.zeros((4, 3)) + 0.5), 'pA', ['regions', '(4, 3)', '(n, 4)'], 'regions of shape (4, 3)')
    expect_error(dict(square, holes=[0.5, 0.5]), 'p', ['holes', '(2,)'], 'holes as a flat list')
    expect_error(dict(square, vertices=np.zeros((4, 3))), 'p', ['vertices', '(4, 3)'], 'vertices of shape (4, 3)')
    expect_error(dict(square, vertex_markers=np.ones((4, 2), dtype=int)), 'p', ['vertex_markers', '(4, 2)'], 'vertex_markers of shape (4, 2)')
    expect_error(dict(first, triangles=np.zeros((t, 4), dtype=int)), 'rp', ['triangles', '(%d, 4)' % t, '(n, 3) or (n, 6)'],
                 'triangles of shape (t, 4)')
    expect_error(dict(square, segments=[[0, 1], [1, 2], [2, 3], [3]]), 'p', ['segments', 'rectangular'], 'ragged segments')
    # Ranges and types: no wrapping, no truncation, no strings or complex numbers taken for numbers.
    wrap = np.array([[0, 1], [1, 2], [2, 3], [3, 2 ** 32]], dtype=np.int64)  # 2^32 wraps to 0 as a C int
    expect_error(dict(square, segments=wrap), 'p', ['segments', '4294967296', 'C int'], 'int64 segment endpoint 2^32')
    expect_error(dict(square, segment_markers=[1, 2, 3, -2 ** 31 - 1]), 'p', ['segment_markers', '-2147483649'],
                 'segment marker below a C int')
    expect_error(dict(square, segments=[[0, 1], [1, 2], [2, 3], [3, 0.5]]), 'p', ['segments', '0.5', 'not an integer'],
                 'float segment endpoint 0.5')
    expect_error(dict(square, segments=[[0, 1], [1, 2], [2, 3], [3, float('nan')]]), 'p', ['segments', 'nan'],
                 'NaN segment endpoint')
    expect_error(dict(square, vertices=[['0', '0'], ['1', '0'], ['1', '1'], ['0', '1']]), 'p', ['vertices', 'real numbers'],
                 'vertices as strings')
    expect_error(dict(square, holes=[[0.5 + 1j, 0.5]]), 'p', ['holes', 'complex'], 'a complex hole point')
    # What the `triangle` package takes is taken: whole floats as indices, 1-D markers, tuples.
    plain = deltri.triangulate(square, 'pq30')
    as_floats = deltri.triangulate(dict(square, segments=np.array(square['segments'], dtype=float)), 'pq30')
    check(np.array_equal(plain['triangles'], as_floats['triangles']), 'segments as whole floats: the same mesh as ints')
    flat = deltri.triangulate(dict(square, vertex_markers=(1, 2, 3, 4), segment_markers=np.array([5, 6, 7, 8])), 'p')
    check(flat['vertex_markers'][:4, 0].tolist() == [1, 2, 3, 4] and sorted(flat['segment_markers'][:, 0].tolist()) == [5, 6, 7, 8],
          'markers as a tuple and a 1-D array: read one per item')
    # Item 12: a NUL in the switches is an error, not the end of them ('p\0q30' was -p alone).
    expect_error(square, 'p\0q30', ['opts', 'NUL', 'position 1'], 'a NUL byte in opts', code=2)
    # The module's own Qz joins the caller's letters: a leading dash or a string of long options alone
    # reaches the parser as the command line would take it.
    counts = []
    for opts in ('q30a0.1', '-q30a0.1', ' q30a0.1', 'q30a0.1 --threads=2'):
        try:
            counts.append(len(deltri.triangulate(square, opts)['triangles']))
        except deltri.DeltriError as e:
            counts.append(str(e))
    check(len(set(counts)) == 1 and isinstance(counts[0], int), "q30a0.1, -q30a0.1, ' q30a0.1', with --threads=2: %s" % counts)
    try:
        check(len(deltri.triangulate(square, '--threads=2')['triangles']) == 2, "'--threads=2' alone: 2 triangles")
    except deltri.DeltriError as e:
        check(False, "'--threads=2' alone: %s" % e)
    # Item 1 through the module: the holes and regions go back with p whatever long options follow.
    holed = dict(square, vertices=[[0, 0], [3, 0], [3, 3], [0, 3], [1, 1], [2, 1], [2, 2], [1, 2]],
                 segments=[[0, 1], [1, 2], [2, 3], [3, 0], [4, 5], [5, 6], [6, 7], [7, 4]], holes=[[1.5, 1.5]])
    for opts in ('pq30', 'pq30 --range-restricted', 'pq30 --threads=2'):
        m = deltri.triangulate(holed, opts)
        returned = np.asarray(m['holes']).tolist() if 'holes' in m else 'none'
        check(abs(areas(m).sum() - 8) < 1e-12 and returned == [[1.5, 1.5]],
              '-%s: area %.15g (8: the hole carved), holes returned: %s' % (opts, areas(m).sum(), returned))
    # The surface mode's input too: a polygon is a list of vertex numbers, a facet's holes rows of 3.
    cube = {'vertices': [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], 'facets': [{'polygons': [[[0, 1], [2, 3]]]}]}
    for facets, words, what in (
            ([{'polygons': [[[0, 1], [2, 3]]]}], ["facets[0]['polygons'][0]", '(2, 2)'], 'surface polygon of shape (2, 2)'),
            ([{'polygons': [[0, 1, 2, 3]], 'holes': [[0.5, 0.5]]}], ["facets[0]['holes']", '(1, 2)'], 'surface hole of shape (1, 2)'),
            ([{'polygons': [[0, 1, 2, 3]], 'marker': 1.5}], ["facets[0]['marker']", '1.5'], 'surface marker 1.5')):
        try:
            deltri.mesh_surface(dict(cube, facets=facets), 'p')
            check(False, '%s: no error' % what)
        except deltri.DeltriError as e:
            check(all(w in str(e) for w in words), '%s: "%s"' % (what, e))
        except Exception as e:  # noqa: BLE001
            check(False, '%s: %s "%s", not DeltriError' % (what, type(e).__name__, e))


def main():
    deltri_path, source_dir = sys.argv[1:3]
    work = tempfile.mkdtemp()
    try:
        # 1. The dict round trip: the module's arrays are the command line's files, value for value.
        for source, opts in (('data/guitar.poly', 'pq30a0.5en'), ('tests/api/inputs/plate_attr.poly', 'pq25aAe'),
                             ('data/box.poly', 'pq30a0.05o2')):
            path = os.path.join(source_dir, source)
            d = read_poly(path)
            got = deltri.triangulate(d, opts)
            want = cli(deltri_path, path, opts + 'z', work)
            keys = sorted(want)
            same = all(k in got and got[k].shape == want[k].shape and np.array_equal(got[k], want[k]) for k in keys)
            check(same, 'round trip %s -%s: %s equal to deltri -%sz\'s files' % (source, opts, ', '.join(keys), opts))
            if 'holes' in d:
                check(np.array_equal(got['holes'], np.array(d['holes'])), 'round trip %s: holes returned as given' % source)
            for k in ('vertices', 'segments', 'triangles'):
                check(k not in got or got[k].flags['C_CONTIGUOUS'], 'round trip %s: %s is a C-contiguous array' % (source, k))
        # 2. The size callback: finer where it asks (x < 0.5), coarse elsewhere.
        square = {'vertices': [[0, 0], [1, 0], [1, 1], [0, 1]], 'segments': [[0, 1], [1, 2], [2, 3], [3, 0]]}

        def size(corners, area):
            x = sum(c[0] for c in corners) / 3.0
            return area > (0.0005 if x < 0.5 else 0.02)
        m = deltri.triangulate(square, 'pq30', size=size)
        a = areas(m)
        cx = m['vertices'][m['triangles']].mean(axis=1)[:, 0]
        left, right = a[cx < 0.5], a[cx >= 0.5]
        check(left.max() <= 0.0005 and right.max() <= 0.02 and math.isclose(a.sum(), 1.0, rel_tol=1e-12),
              'size callback: every triangle within its asked area (left %.2e <= 5e-4, right %.2e <= 2e-2), areas sum to 1' %
              (left.max(), right.max()))
        check(left.mean() * 3 < right.mean() and len(left) > 3 * len(right),
              'size callback: finer where asked (%d triangles of mean area %.2e left of x = 0.5, %d of %.2e right)' %
              (len(left), left.mean(), len(right), right.mean()))
        plain = deltri.triangulate(square, 'pq30')
        check(len(plain['triangles']) < len(right), 'size callback: without it %d triangles' % len(plain['triangles']))
        # 3. Errors: the library's message as DeltriError; the callback's own exception passes through.
        try:
            deltri.triangulate({'vertices': [[0, 0], [1, 0], [0, 1]], 'segments': [[0, 1], [1, 7]]}, 'p')
            check(False, 'bad segment: no exception')
        except deltri.DeltriError as e:
            check(str(e) == 'segment 1: second endpoint 7 is not a vertex (vertices are numbered 0 to 2)' and e.code == 1,
                  'bad segment: DeltriError "%s"' % e)
        try:
            deltri.triangulate({'vertices': [[0, 0], [1, 0], [float('nan'), 1]]}, '')
            check(False, 'NaN: no exception')
        except deltri.DeltriError as e:
            check('vertex 2: x coordinate is not a finite number (nan)' in str(e), 'NaN vertex: DeltriError "%s"' % e)
        try:
            deltri.triangulate(square, 'pq70')
            check(False, 'q70: no exception')
        except deltri.DeltriError as e:
            check(e.code == 2, 'switch q70: DeltriError "%s"' % e)

        def broken(corners, area):
            raise ValueError('from the callback')
        try:
            deltri.triangulate(square, 'pq', size=broken)
            check(False, 'callback exception: none raised')
        except ValueError as e:
            check(str(e) == 'from the callback', 'callback exception: raised to the caller as it was')
        # 4. r: the output refined again through the dict.
        first = deltri.triangulate(square, 'pq30')
        again = deltri.triangulate(first, 'rpq30a0.01')
        check(areas(again).max() <= 0.01 and len(again['triangles']) > len(first['triangles']),
              'r: the output refined again to area 0.01 (%d -> %d triangles)' % (len(first['triangles']), len(again['triangles'])))
        # 5. Issue 17 item 9, the same rule as the command line's: a region point exactly on a segment
        # (here on the segment at y = 0.1 that splits the unit square) has no side and is ignored;
        # one inside a part applies to that part only.
        split = {'vertices': [[0, 0], [1, 0], [1, 1], [0, 1], [0, 0.1], [1, 0.1]],
                 'segments': [[0, 1], [1, 5], [5, 2], [2, 3], [3, 4], [4, 0], [4, 5]]}
        for at, expected in (([0.5, 0.1], 'none'), ([0, 0.1], 'none'), ([0.5, 0.05], 'below')):
            m = deltri.triangulate(dict(split, regions=[at + [7, 0.001]]), 'pA')
            ys = m['vertices'][m['triangles']].mean(axis=1)[:, 1]
            seven = m['triangle_attributes'][:, 0] == 7
            got = 'none' if not seven.any() else 'below' if (seven == (ys < 0.1)).all() else 'mixed'
            check(got == expected, 'region point at (%g, %g): attribute 7 on %s of the triangles (%s expected)' %
                  (at[0], at[1], got, expected))
        check(deltri.version().count('.') == 2, 'version %s' % deltri.version())
        arrays(square)

    finally:
        shutil.rmtree(work)
    finish()


main()
