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


# The rest of the `triangle` package's interface (drufat's Python wrapper of Triangle), so that code
# written for it runs with `import deltri as triangle`: delaunay, convex_hull, voronoi, loads, load,
# get_data, show_data, plot, compare and comparev, with its argument forms and results
# (docs/library.md, "The triangle package's other functions").

__version__ = version()
__all__ += ['delaunay', 'convex_hull', 'voronoi', 'loads', 'load', 'get_data', 'get_data_dir', 'show_data',
            'plot', 'compare', 'comparev', '__version__']


def _points(pts):
    return {'vertices': pts}


def delaunay(pts):
    """The Delaunay triangulation of the points pts ((n, 2)): its triangles, (t, 3) vertex numbers
    from 0, counter-clockwise."""
    return triangulate(_points(pts), '')['triangles']


def convex_hull(pts):
    """The convex hull of the points pts ((n, 2)): its edges as segments, (h, 2) vertex numbers."""
    return triangulate(_points(pts), 'c')['segments']


def voronoi(pts):
    """The Voronoi diagram of the points pts: (points, edges, ray_origins, ray_directions), the
    Voronoi vertices (m, 2), the finite edges (k, 2), and for each infinite edge (ray) the Voronoi
    vertex it starts at (r,) and its direction (r, 2)."""
    m = triangulate(_points(pts), 'v')
    points = m.get('voronoi_vertices', np.zeros((0, 2)))
    edges = m.get('voronoi_edges', np.zeros((0, 2), dtype=np.intc))
    directions = m.get('voronoi_ray_directions', np.zeros((0, 2)))
    ray = edges[:, 1] == -1
    return points, edges[~ray], edges[ray][:, 0], directions[ray]


class _Table:
    """The numbers of one Triangle file (.node, .ele, .poly, ...), line by line without comments, read
    the way the `triangle` package reads them; an error names the file and the line."""

    def __init__(self, kind, text):
        self.kind, self.rows = kind, []
        for number, line in enumerate(text.splitlines(), 1):
            words = line.split('#', 1)[0].split()
            if words:
                self.rows.append((number, words))
        self.at = 0

    def fail(self, what, number=None):
        where = '%s: line %d' % (self.kind, number) if number else self.kind
        _fail('%s: %s' % (where, what))

    def take(self, count, least):
        """The next `count` rows, each with at least `least` numbers."""
        if self.at + count > len(self.rows):
            self.fail('the file ends after %d of %d items' % (len(self.rows) - self.at, count))
        rows = self.rows[self.at:self.at + count]
        self.at += count
        for number, words in rows:
            if len(words) < least:
                self.fail('%d numbers, at least %d expected' % (len(words), least), number)
        return rows

    def header(self, least, defaults):
        """The header line's numbers (missing trailing ones from defaults); None at the end."""
        if self.at >= len(self.rows):
            return None
        number, words = self.take(1, least)[0]
        try:
            values = [int(w) for w in words[:len(defaults)]]
        except ValueError:
            self.fail('the header "%s" is not a list of whole numbers' % ' '.join(words), number)
        if any(v < 0 for v in values):
            self.fail('a negative count in the header "%s"' % ' '.join(words), number)
        return values + defaults[len(values):]

    def numbers(self, rows, first, last, dtype):
        try:
            return np.array([[float(w) for w in words[first:last]] for _, words in rows]).astype(dtype)
        except ValueError as e:
            self.fail(str(e), rows[0][0])


def _loads_vertices(table, data, numbering):
    head = table.header(1, [0, 2, 0, 0])
    if head is None or head[0] == 0:
        return
    n, dimension, attributes, markers = head
    rows = table.take(n, 1 + dimension + attributes + markers)
    numbering[0] = int(float(rows[0][1][0]))
    data['vertices'] = table.numbers(rows, 1, 3, np.float64)
    if attributes:
        data['vertex_attributes'] = table.numbers(rows, 1 + dimension, 1 + dimension + attributes, np.float64)
    if markers:
        start = 1 + dimension + attributes
        data['vertex_markers'] = table.numbers(rows, start, start + 1, np.intc)


def _loads_poly(table, data, numbering):
    _loads_vertices(table, data, numbering)
    head = table.header(1, [0, 0])
    if head is None:
        return
    rows = table.take(head[0], 3 + head[1])
    if rows:
        data['segments'] = table.numbers(rows, 1, 3, np.intc) - numbering[0]
        if head[1]:
            data['segment_markers'] = table.numbers(rows, 3, 4, np.intc)
    head = table.header(1, [0])
    rows = table.take(head[0], 3) if head else []
    if rows:
        data['holes'] = table.numbers(rows, 1, 3, np.float64)
    head = table.header(1, [0])
    rows = table.take(head[0], 4) if head else []
    if rows:
        # x, y, attribute, area; a line with one value after x and y (la.poly) gives its area bound and
        # attribute 0, as the `triangle` package reads it.
        data['regions'] = np.array([[float(w) for w in words[1:3]] +
                                    ([float(w) for w in words[3:5]] if len(words) >= 5 else [0.0, float(words[3])])
                                    for _, words in rows])


def _loads_ele(table, data, numbering):
    head = table.header(1, [0, 3, 0])
    if head is None or head[0] == 0:
        return
    t, corners, attributes = head
    rows = table.take(t, 1 + corners + attributes)
    data['triangles'] = table.numbers(rows, 1, 1 + corners, np.intc) - numbering[0]
    if attributes:
        data['triangle_attributes'] = table.numbers(rows, 1 + corners, 1 + corners + attributes, np.float64)


def _loads_edge(table, data, numbering):
    head = table.header(1, [0, 0])
    if head is None or head[0] == 0:
        return
    rows = table.take(head[0], 3)
    rays = [r for r in rows if int(float(r[1][2])) == -1]
    finite = [r for r in rows if int(float(r[1][2])) != -1]
    if finite:
        data['edges'] = table.numbers(finite, 1, 3, np.intc) - numbering[0]
        if head[1]:
            data['edge_markers'] = table.numbers(finite, 3, 4, np.intc)
    if rays:
        bad = [number for number, words in rays if len(words) < 5]
        if bad:
            table.fail('a ray (second end -1) without its direction', bad[0])
        data['ray_origins'] = table.numbers(rays, 1, 2, np.intc) - numbering[0]
        data['ray_directions'] = table.numbers(rays, 3, 5, np.float64)


def _loads_area(table, data, numbering):
    head = table.header(1, [0])
    if head and head[0]:
        data['triangle_max_area'] = table.numbers(table.take(head[0], 2), 1, 2, np.float64)


def _loads_neigh(table, data, numbering):
    head = table.header(1, [0, 3])
    if head and head[0]:
        neighbors = table.numbers(table.take(head[0], 1 + head[1]), 1, 1 + head[1], np.intc)
        data['triangle_neighbors'] = np.where(neighbors >= 0, neighbors - numbering[0], neighbors)


def loads(node=None, ele=None, poly=None, area=None, edge=None, neigh=None):
    """The dict of Triangle files given as strings (.node, .ele, .poly, .area, .edge, .neigh), with
    the `triangle` package's keys, numbered from 0 (files that number from 1 are renumbered, as the
    first vertex's number says). Raises DeltriError (a ValueError) naming the file and line."""
    data, numbering = {}, [0]
    for kind, text, reader in (('node', node, _loads_vertices), ('poly', poly, _loads_poly), ('ele', ele, _loads_ele),
                               ('area', area, _loads_area), ('edge', edge, _loads_edge),
                               ('neigh', neigh, _loads_neigh)):
        if text:
            reader(_Table(kind, text), data, numbering)
    return data


def load(directory, name):
    """loads() on the files directory/name.node, .ele, .poly, .area, .edge and .neigh that exist."""
    texts = {}
    for kind in ('node', 'ele', 'poly', 'area', 'edge', 'neigh'):
        path = os.path.join(directory, name + '.' + kind)
        if os.path.exists(path):
            with open(path) as f:
                texts[kind] = f.read()
    return loads(**texts)


def _data_dirs():
    """Where get_data looks: $DELTRI_TRIANGLE_DATA (folders separated by ':'), then the data folder
    of the `triangle` package where it is installed. deltri ships none of its samples (their
    licences are not deltri's; docs/library.md)."""
    dirs = [d for d in os.environ.get('DELTRI_TRIANGLE_DATA', '').split(os.pathsep) if d]
    try:
        import importlib.util
        spec = importlib.util.find_spec('triangle')
    except (ImportError, ValueError):
        spec = None
    if spec is not None and spec.submodule_search_locations:
        dirs += [os.path.join(location, 'data') for location in spec.submodule_search_locations]
    return [d for d in dirs if os.path.isdir(d)]


def get_data_dir():
    """The first folder get_data looks in (None when there is none)."""
    dirs = _data_dirs()
    return dirs[0] if dirs else None


def get_data(name):
    """The sample `name` ('A', 'dots', 'face.1', ...) as a dict, from the first folder that has one of
    its files: $DELTRI_TRIANGLE_DATA, else the installed `triangle` package's data folder."""
    dirs = _data_dirs()
    for d in dirs:
        if any(os.path.exists(os.path.join(d, name + '.' + k)) for k in ('node', 'ele', 'poly', 'area', 'edge', 'neigh')):
            return load(d, name)
    _fail("get_data: no sample '%s' in %s; deltri ships none of the triangle package's samples: set "
          "DELTRI_TRIANGLE_DATA to a folder of Triangle files (docs/library.md)" %
          (name, ', '.join(dirs) if dirs else 'any folder (DELTRI_TRIANGLE_DATA is not set and the triangle package is not installed)'))


def _pyplot():
    try:
        import matplotlib.pyplot as plt
    except ImportError as e:
        raise ImportError('deltri: plotting needs matplotlib (Debian: apt-get install python3-matplotlib; '
                          'or pip install matplotlib): %s' % e) from e
    return plt


def show_data(name):
    """Plots the sample `name` (get_data) with matplotlib and shows it."""
    plt = _pyplot()
    plot(plt.axes(), **get_data(name))
    plt.show()


def _lines(ax, vertices, pairs, **style):
    from matplotlib.collections import LineCollection
    if len(pairs):
        ax.add_collection(LineCollection(vertices[np.asarray(pairs)], **style))


def plot(ax=None, **kw):
    """Draws a dict with the `triangle` package's keys on the matplotlib axes `ax` (new axes when
    None): vertices as dots, segments in red, triangles' edges, holes as crosses, edges with the
    Voronoi rays (ray_origins, ray_directions), region points and triangle attributes labelled;
    labels=True numbers the vertices, markers=True writes their vertex_markers."""
    if ax is None:
        ax = _pyplot().axes()
    ax.set_aspect('equal')
    vertices = np.asarray(kw['vertices'], dtype=np.float64).reshape(-1, 2)
    ax.scatter(vertices[:, 0], vertices[:, 1], s=8, color='k', zorder=3)
    # labels=True numbers the vertices, markers=True writes their markers, as in the package.
    texts = (range(len(vertices)) if kw.get('labels') else
             np.asarray(kw['vertex_markers']).reshape(-1) if kw.get('markers') and 'vertex_markers' in kw else None)
    if texts is not None:
        for (x, y), text in zip(vertices.tolist(), texts):
            ax.text(x, y, str(text))
    if 'triangles' in kw and len(kw['triangles']):
        corners = np.asarray(kw['triangles'])[:, :3]
        _lines(ax, vertices, np.concatenate([corners[:, [0, 1]], corners[:, [1, 2]], corners[:, [2, 0]]]),
               colors='k', linewidths=0.5, zorder=1)
    if 'segments' in kw:
        _lines(ax, vertices, kw['segments'], colors='r', linewidths=2.5, zorder=2)
    if 'edges' in kw:
        _lines(ax, vertices, kw['edges'], colors='k', linewidths=0.5, zorder=1)
    ax.autoscale_view()
    if 'ray_origins' in kw and 'ray_directions' in kw and len(kw['ray_origins']):
        # A ray is drawn to well past the current view, which is kept.
        limits = ax.axis()
        reach = 100.0 * max(limits[1] - limits[0], limits[3] - limits[2], 1.0)
        start = vertices[np.asarray(kw['ray_origins']).reshape(-1)]
        direction = np.asarray(kw['ray_directions'], dtype=np.float64).reshape(-1, 2)
        length = np.maximum(np.hypot(direction[:, 0], direction[:, 1]), 1e-300)
        from matplotlib.collections import LineCollection
        ax.add_collection(LineCollection(np.stack([start, start + direction * (reach / length)[:, None]], axis=1),
                                         colors='k', linewidths=0.5, zorder=1))
        ax.axis(limits)
    if 'holes' in kw and len(kw['holes']):
        holes = np.asarray(kw['holes'], dtype=np.float64).reshape(-1, 2)
        ax.scatter(holes[:, 0], holes[:, 1], marker='x', color='r', zorder=4)
    if 'regions' in kw and len(kw['regions']):
        regions = np.asarray(kw['regions'], dtype=np.float64).reshape(-1, 4)
        ax.scatter(regions[:, 0], regions[:, 1], marker='*', color='b', zorder=4)
        for x, y, attribute, _ in regions:
            ax.text(x, y, ' %g' % attribute, color='b', va='center')
    if 'triangle_attributes' in kw and 'triangles' in kw and len(kw['triangles']):
        centres = vertices[np.asarray(kw['triangles'])[:, :3]].mean(axis=1)
        values = np.asarray(kw['triangle_attributes']).reshape(len(centres), -1)[:, 0]
        for (x, y), value in zip(centres, values):
            ax.text(x, y, '%g' % value, color='m', fontsize='x-small', ha='center', va='center')
    ax.get_xaxis().set_visible(False)
    ax.get_yaxis().set_visible(False)
    return ax


def _pair(plt, A, B, figsize, first, second, shared):
    plt.figure(figsize=figsize)
    left = plt.subplot(first)
    plot(left, **A)
    limits = left.axis()
    right = plt.subplot(second, **{shared: left})
    plot(right, **B)
    right.axis(limits)
    plt.tight_layout()


def compare(plt, A, B, figsize=(6, 3)):
    """A and B side by side (plt is matplotlib.pyplot), B in A's frame."""
    _pair(plt, A, B, figsize, 121, 122, 'sharey')


def comparev(plt, A, B, figsize=(3, 6)):
    """A above B (plt is matplotlib.pyplot), B in A's frame."""
    _pair(plt, A, B, figsize, 211, 212, 'sharex')
