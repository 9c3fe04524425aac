"""deltri for Python: a 2-D quality mesh generator with the `triangle` package's interface.

    import deltri
    mesh = deltri.triangulate({'vertices': [[0, 0], [1, 0], [1, 1], [0, 1]],
                               'segments': [[0, 1], [1, 2], [2, 3], [3, 0]]}, 'pq30a0.1')
    mesh['vertices'], mesh['triangles']      # numpy arrays

ctypes over the shared library libdeltri (found from $DELTRI_LIBRARY, next to this module's
install prefix, or by the dynamic linker) and numpy. See docs/library.md.
"""
import ctypes
import os

import numpy as np

__all__ = ['triangulate', 'mesh_surface', 'DeltriError', 'version']


class DeltriError(ValueError):
    """A bad input or switch string: str(e) is the one-line message naming the key or switch, e.code
    the status (1 input, 2 switches; deltri/triangle.h). A ValueError, as the `triangle` package's
    errors are."""

    def __init__(self, code, message):
        super().__init__(message)
        self.code = code


_D = ctypes.POINTER(ctypes.c_double)
_I = ctypes.POINTER(ctypes.c_int)


class _TriangulateIO(ctypes.Structure):
    # Triangle's struct triangulateio, field by field (deltri/triangle.h).
    _fields_ = [('pointlist', _D), ('pointattributelist', _D), ('pointmarkerlist', _I),
                ('numberofpoints', ctypes.c_int), ('numberofpointattributes', ctypes.c_int),
                ('trianglelist', _I), ('triangleattributelist', _D), ('trianglearealist', _D),
                ('neighborlist', _I), ('numberoftriangles', ctypes.c_int), ('numberofcorners', ctypes.c_int),
                ('numberoftriangleattributes', ctypes.c_int),
                ('segmentlist', _I), ('segmentmarkerlist', _I), ('numberofsegments', ctypes.c_int),
                ('holelist', _D), ('numberofholes', ctypes.c_int),
                ('regionlist', _D), ('numberofregions', ctypes.c_int),
                ('edgelist', _I), ('edgemarkerlist', _I), ('normlist', _D), ('numberofedges', ctypes.c_int)]


class _Facets(ctypes.Structure):
    # struct deltri_facets (deltri/triangle.h).
    _fields_ = [('pointlist', _D), ('pointmarkerlist', _I), ('numberofpoints', ctypes.c_int),
                ('cornerlist', _I), ('polygonsizelist', _I), ('numberofpolygons', ctypes.c_int),
                ('holelist', _D), ('numberofholes', ctypes.c_int),
                ('facetpolygonlist', _I), ('facetholelist', _I), ('facetmarkerlist', _I), ('numberoffacets', ctypes.c_int)]


class _Surface(ctypes.Structure):
    # struct deltri_surface (deltri/triangle.h).
    _fields_ = [('pointlist', _D), ('pointmarkerlist', _I), ('numberofpoints', ctypes.c_int),
                ('trianglelist', _I), ('triangleattributelist', _D), ('trianglefacetlist', _I),
                ('numberoftriangles', ctypes.c_int),
                ('edgelist', _I), ('edgemarkerlist', _I), ('numberofedges', ctypes.c_int),
                ('mergedpointlist', _I), ('numberofmergedpoints', ctypes.c_int),
                ('emptiedfacetlist', _I), ('numberofemptiedfacets', ctypes.c_int),
                ('budgetreached', ctypes.c_int), ('roundsexhausted', ctypes.c_int),
                ('numberbelowangle', ctypes.c_int), ('numberabovearea', ctypes.c_int)]


class _Status(ctypes.Structure):
    _fields_ = [('code', ctypes.c_int), ('message', ctypes.c_char * 512)]


_SIZE_TEST = ctypes.CFUNCTYPE(ctypes.c_int, _D, _D, _D, ctypes.c_double, ctypes.c_void_p)


def _load():
    here = os.path.dirname(os.path.abspath(__file__))
    candidates = [os.environ.get('DELTRI_LIBRARY'),
                  # PREFIX/lib/python3.X/dist-packages/deltri -> PREFIX/lib
                  os.path.join(here, '..', '..', '..', 'libdeltri.so.0'),
                  'libdeltri.so.0']
    errors = []
    for path in candidates:
        if not path:
            continue
        try:
            lib = ctypes.CDLL(path)
            break
        except OSError as e:
            errors.append(str(e))
    else:
        raise ImportError('deltri: cannot load libdeltri.so.0 (set DELTRI_LIBRARY): ' + '; '.join(errors))
    io = ctypes.POINTER(_TriangulateIO)
    lib.deltri_triangulate_sized.argtypes = [ctypes.c_char_p, io, io, io, _SIZE_TEST, ctypes.c_void_p,
                                             ctypes.POINTER(_Status)]
    lib.deltri_triangulate_sized.restype = ctypes.c_int
    lib.deltri_mesh_surface.argtypes = [ctypes.c_char_p, ctypes.POINTER(_Facets), ctypes.POINTER(_Surface),
                                        ctypes.POINTER(_Status)]
    lib.deltri_mesh_surface.restype = ctypes.c_int
    lib.deltri_surface_free.argtypes = [ctypes.POINTER(_Surface)]
    lib.trifree.argtypes = [ctypes.c_void_p]
    lib.deltri_version.restype = ctypes.c_char_p
    return lib


_lib = _load()


def version():
    return _lib.deltri_version().decode()


_INT_MIN, _INT_MAX = -2 ** 31, 2 ** 31 - 1


def _fail(message, code=1):
    raise DeltriError(code, message)


def _shape(a):
    return '(%s)' % ', '.join(str(n) for n in a.shape) if a.ndim != 1 else '(%d,)' % a.shape[0]


def _numbers(value, key, integer, allow_bool=False):
    """value as a numpy array of C doubles or ints, or None when it is None or empty. Integers
    given as floats must be whole; every integer must fit a C int (no wrapping, no truncation)."""
    if value is None:
        return None
    try:
        a = np.asarray(value)
    except (ValueError, TypeError):
        _fail('%s: not a rectangular array of numbers (rows of different lengths?)' % key)
    if a.size == 0:
        return None
    kinds = 'iuf' + ('b' if allow_bool else '')
    if a.dtype.kind not in kinds:
        _fail('%s: the values must be %s, not %s' % (key, 'integers' if integer else 'real numbers', a.dtype))
    if not integer:
        return a.astype(np.float64)
    if a.dtype.kind == 'f':
        flat = a.reshape(-1)
        with np.errstate(invalid='ignore'):
            bad = ~np.isfinite(flat) | (flat != np.trunc(flat))
        if bad.any():
            _fail('%s: %r is not an integer' % (key, flat[bad][0].item()))
    if a.dtype.kind != 'b':
        low, high = a.min().item(), a.max().item()
        for v in (low, high):
            if v < _INT_MIN or v > _INT_MAX:
                _fail('%s: %d is outside the range of a C int (%d to %d)' % (key, v, _INT_MIN, _INT_MAX))
    return a.astype(np.intc)


def _rows(value, key, integer, columns):
    """An (n, columns) array, columns one of the given counts; None when absent or empty."""
    a = _numbers(value, key, integer)
    if a is None:
        return None
    if a.ndim != 2 or a.shape[1] not in columns:
        _fail('%s: shape %s is not %s' % (key, _shape(a), ' or '.join('(n, %d)' % c for c in columns)))
    return np.ascontiguousarray(a)


def _per_item(value, key, integer, items, what, table=False):
    """One value per item, (n,) or (n, 1), or with `table` (n, k) rows of k values; n must be `items`."""
    a = _numbers(value, key, integer, allow_bool=integer)
    if a is None:
        return None
    if a.ndim == 1:
        a = a.reshape(-1, 1)
    elif a.ndim != 2 or (a.shape[1] != 1 and not table):
        _fail('%s: shape %s is not %s' % (key, _shape(a), '(n,) or (n, k)' if table else '(n,) or (n, 1)'))
    if len(a) != items:
        unit = 'row' if a.shape[1] > 1 else 'value'
        _fail('%s: %d %s%s for %d %s, expected %d' % (key, len(a), unit, '' if len(a) == 1 else 's', items, what, items))
    return np.ascontiguousarray(a)


def _count(a, key):
    n = 0 if a is None else len(a)
    if n > _INT_MAX:
        _fail('%s: %d items, more than a C int counts' % (key, n))
    return n


def _set(io, field, array, keep):
    if array is None:
        return
    keep.append(array)
    ctype = _D if array.dtype == np.float64 else _I
    setattr(io, field, array.ctypes.data_as(ctype))


def _vertices(d, io, keep, dimension):
    vertices = _rows(d.get('vertices'), 'vertices', False, (dimension,))
    if vertices is None:
        _fail("the input has no 'vertices'")
    io.numberofpoints = _count(vertices, 'vertices')
    _set(io, 'pointlist', vertices, keep)
    markers = _per_item(d.get('vertex_markers'), 'vertex_markers', True, io.numberofpoints, 'vertices')
    _set(io, 'pointmarkerlist', markers, keep)


def _fill_input(d, io, keep):
    """The dict's arrays into io, each checked for shape, type, range and length against its items
    (the library reads as many values as the counts say; a short array would be read past its end)."""
    _vertices(d, io, keep, 2)
    n = io.numberofpoints
    attributes = _per_item(d.get('vertex_attributes'), 'vertex_attributes', False, n, 'vertices', table=True)
    if attributes is not None:
        io.numberofpointattributes = attributes.shape[1]
        _set(io, 'pointattributelist', attributes, keep)
    segments = _rows(d.get('segments'), 'segments', True, (2,))
    io.numberofsegments = _count(segments, 'segments')
    _set(io, 'segmentlist', segments, keep)
    _set(io, 'segmentmarkerlist',
         _per_item(d.get('segment_markers'), 'segment_markers', True, io.numberofsegments, 'segments'), keep)
    holes = _rows(d.get('holes'), 'holes', False, (2,))
    io.numberofholes = _count(holes, 'holes')
    _set(io, 'holelist', holes, keep)
    regions = _rows(d.get('regions'), 'regions', False, (4,))
    io.numberofregions = _count(regions, 'regions')
    _set(io, 'regionlist', regions, keep)
    triangles = _rows(d.get('triangles'), 'triangles', True, (3, 6))
    io.numberoftriangles = _count(triangles, 'triangles')
    if triangles is not None:
        io.numberofcorners = triangles.shape[1]
        _set(io, 'trianglelist', triangles, keep)
    t = io.numberoftriangles
    attributes = _per_item(d.get('triangle_attributes'), 'triangle_attributes', False, t, 'triangles', table=True)
    if attributes is not None:
        io.numberoftriangleattributes = attributes.shape[1]
        _set(io, 'triangleattributelist', attributes, keep)
    _set(io, 'trianglearealist', _per_item(d.get('triangle_max_area'), 'triangle_max_area', False, t, 'triangles'), keep)
    return holes, regions


def _copy(pointer, count, columns, dtype):
    """Copies count x columns values of an array the library owns (released afterwards as a whole)."""
    if not pointer or count <= 0 or columns <= 0:
        return None
    return np.ctypeslib.as_array(pointer, shape=(count * columns,)).astype(dtype).reshape(count, columns)


def _take(pointer, count, columns, dtype):
    """Copies count x columns values the library allocated, then releases them."""
    a = _copy(pointer, count, columns, dtype)
    if a is not None:
        _lib.trifree(ctypes.cast(pointer, ctypes.c_void_p))
    return a


def _output(out, vor):
    r = {}
    items = [('vertices', out.pointlist, out.numberofpoints, 2, np.float64),
             ('vertex_attributes', out.pointattributelist, out.numberofpoints, out.numberofpointattributes, np.float64),
             ('vertex_markers', out.pointmarkerlist, out.numberofpoints, 1, np.intc),
             ('triangles', out.trianglelist, out.numberoftriangles, out.numberofcorners, np.intc),
             ('triangle_attributes', out.triangleattributelist, out.numberoftriangles, out.numberoftriangleattributes, np.float64),
             ('neighbors', out.neighborlist, out.numberoftriangles, 3, np.intc),
             ('segments', out.segmentlist, out.numberofsegments, 2, np.intc),
             ('segment_markers', out.segmentmarkerlist, out.numberofsegments, 1, np.intc),
             ('edges', out.edgelist, out.numberofedges, 2, np.intc),
             ('edge_markers', out.edgemarkerlist, out.numberofedges, 1, np.intc)]
    if vor is not None:
        items += [('voronoi_vertices', vor.pointlist, vor.numberofpoints, 2, np.float64),
                  ('voronoi_vertex_attributes', vor.pointattributelist, vor.numberofpoints, vor.numberofpointattributes, np.float64),
                  ('voronoi_edges', vor.edgelist, vor.numberofedges, 2, np.intc),
                  ('voronoi_ray_directions', vor.normlist, vor.numberofedges, 2, np.float64)]
    for key, pointer, count, columns, dtype in items:
        a = _take(pointer, count, columns, dtype)
        if a is not None:
            r[key] = a
    return r


def _switches(opts, added):
    """The switch string with the module's own letters joined to the caller's word of letters (a
    leading dash dropped, as Triangle ignores it), or put before the long options when there is none."""
    if '\0' in opts:
        _fail('opts: a NUL character at position %d would end the switches there' % opts.index('\0'), 2)
    rest = opts.lstrip(' \t')
    if rest.startswith('--') or not rest:
        return (added + ' ' + rest).rstrip().encode()
    return (added + (rest[1:] if rest.startswith('-') else rest)).encode()


def triangulate(d, opts='', size=None):
    """Triangulates the dict d (the `triangle` package's keys: vertices, vertex_markers,
    vertex_attributes, segments, segment_markers, holes, regions, and for 'r' triangles,
    triangle_attributes, triangle_max_area) with Triangle's switches `opts` (no dash); numbering
    is from 0 (z is always added) and nothing is printed (Q). Returns a dict with the same keys
    (and neighbors, edges, edge_markers as the switches ask; with 'v' voronoi_vertices,
    voronoi_edges, voronoi_ray_directions). `size`, if given, is called as
    size(((x0, y0), (x1, y1), (x2, y2)), area) for triangles during refinement: a true result
    means too big, split it. Raises DeltriError on bad input."""
    switches = _switches(opts, 'Qz')
    keep = []
    io_in, io_out, io_vor = _TriangulateIO(), _TriangulateIO(), _TriangulateIO()
    holes, regions = _fill_input(d, io_in, keep)
    # The library sets the output's hole count when the switches it parsed say p without r (then the
    # input's holes and regions are the output's); left at -1 it says they are not.
    io_out.numberofholes = -1
    thrown = []

    def test(org, dest, apex, area, user):
        if thrown:
            return 0
        try:
            corners = ((org[0], org[1]), (dest[0], dest[1]), (apex[0], apex[1]))
            return 1 if size(corners, area) else 0
        except BaseException as e:  # carried out of the C call and raised there
            thrown.append(e)
            return 0

    callback = _SIZE_TEST(test) if size is not None else _SIZE_TEST()
    status = _Status()
    code = _lib.deltri_triangulate_sized(switches, ctypes.byref(io_in), ctypes.byref(io_out),
                                         ctypes.byref(io_vor), callback, None, ctypes.byref(status))
    if thrown:
        _output(io_out, io_vor)  # release what was made
        raise thrown[0]
    if code != 0:
        raise DeltriError(code, status.message.decode(errors='replace'))
    poly = io_out.numberofholes >= 0
    result = _output(io_out, io_vor)  # the Voronoi arrays are there only when v asked for them
    for key, given, columns in (('holes', holes, 2), ('regions', regions, 4)):
        if poly and key in d:
            result[key] = given.copy() if given is not None else np.zeros((0, columns))
    return result


def _facets_in(d, io, keep):
    _vertices(d, io, keep, 3)
    corners, sizes, per_facet, holes, holes_per_facet, markers = [], [], [], [], [], []
    for f, facet in enumerate(d.get('facets', [])):
        key = 'facets[%d]' % f
        polygons = facet.get('polygons', [])
        per_facet.append(len(polygons))
        for k, polygon in enumerate(polygons):
            name = "%s['polygons'][%d]" % (key, k)
            polygon = _numbers(polygon, name, True)
            if polygon is None:  # the library says what is wrong with an empty polygon
                polygon = np.zeros(0, dtype=np.intc)
            if polygon.ndim > 1:
                _fail('%s: shape %s is not (k,), a list of vertex numbers' % (name, _shape(polygon)))
            polygon = polygon.reshape(-1)
            sizes.append(len(polygon))
            corners.extend(polygon.tolist())
        facet_holes = _rows(facet.get('holes'), "%s['holes']" % key, False, (3,))
        facet_holes = np.zeros((0, 3)) if facet_holes is None else facet_holes
        holes_per_facet.append(len(facet_holes))
        holes.extend(facet_holes.reshape(-1).tolist())
        marker = _numbers(facet.get('marker', 0), "%s['marker']" % key, True, allow_bool=True)
        if marker is not None and marker.ndim != 0:
            _fail("%s['marker']: shape %s is not a single number" % (key, _shape(marker)))
        markers.append(0 if marker is None else int(marker))
    lists = [('cornerlist', corners, np.intc), ('polygonsizelist', sizes, np.intc), ('holelist', holes, np.float64),
             ('facetpolygonlist', per_facet, np.intc), ('facetholelist', holes_per_facet, np.intc),
             ('facetmarkerlist', markers, np.intc)]
    for field, values, dtype in lists:
        _set(io, field, np.ascontiguousarray(values, dtype=dtype) if values else None, keep)
    io.numberofpolygons, io.numberofholes, io.numberoffacets = len(sizes), len(holes) // 3, len(per_facet)


def mesh_surface(d, opts=''):
    """Meshes facets in 3-D (docs/surfaces.md): d has 'vertices' (n x 3), optionally
    'vertex_markers', and 'facets', a list of dicts with 'polygons' (lists of vertex numbers from
    0: one is a vertex in the facet, two a segment, three or more a closed loop), optionally
    'holes' (points in the facet's plane, k x 3) and 'marker'. `opts` are Triangle's switches as
    for the command line on a 3-D .poly ('pq30a0.02'); numbering is from 0 (z is always added).
    Returns a dict of numpy arrays: vertices (m x 3), vertex_markers (when given, unless 'B'),
    triangles (t x 3), triangle_attributes (t x 1, the facet markers), triangle_facets (t), edges
    (the subsegments, s x 2) and edge_markers (unless 'B'); what the mesh is not, as the command line
    warns of it: merged_vertices (k x 2: a vertex repeating an earlier one's coordinates, that one),
    emptied_facets, budget_reached, rounds_exhausted, triangles_below_angle and triangles_above_area
    (counted when either flag is set). Raises DeltriError on bad input."""
    switches = _switches(opts, 'z')
    keep = []
    io_in, io_out, status = _Facets(), _Surface(), _Status()
    _facets_in(d, io_in, keep)
    code = _lib.deltri_mesh_surface(switches, ctypes.byref(io_in), ctypes.byref(io_out),
                                    ctypes.byref(status))
    if code != 0:
        raise DeltriError(code, status.message.decode(errors='replace'))
    items = [('vertices', io_out.pointlist, io_out.numberofpoints, 3, np.float64),
             ('vertex_markers', io_out.pointmarkerlist, io_out.numberofpoints, 1, np.intc),
             ('triangles', io_out.trianglelist, io_out.numberoftriangles, 3, np.intc),
             ('triangle_attributes', io_out.triangleattributelist, io_out.numberoftriangles, 1, np.float64),
             ('triangle_facets', io_out.trianglefacetlist, io_out.numberoftriangles, 1, np.intc),
             ('edges', io_out.edgelist, io_out.numberofedges, 2, np.intc),
             ('edge_markers', io_out.edgemarkerlist, io_out.numberofedges, 1, np.intc),
             ('merged_vertices', io_out.mergedpointlist, io_out.numberofmergedpoints, 2, np.intc),
             ('emptied_facets', io_out.emptiedfacetlist, io_out.numberofemptiedfacets, 1, np.intc)]
    result = {}
    for key, pointer, count, columns, dtype in items:
        a = _copy(pointer, count, columns, dtype)
        if a is not None:
            result[key] = a.reshape(-1) if key in ('triangle_facets', 'emptied_facets') else a
    # What the mesh is not, as the command line warns of it.
    result['budget_reached'] = bool(io_out.budgetreached)
    result['rounds_exhausted'] = bool(io_out.roundsexhausted)
    result['triangles_below_angle'] = io_out.numberbelowangle
    result['triangles_above_area'] = io_out.numberabovearea
    _lib.deltri_surface_free(ctypes.byref(io_out))
    return result
