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


class DeltriError(Exception):
    """A bad input or switch string: str(e) is the library's one-line message, e.code its status."""

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
                ('edgelist', _I), ('edgemarkerlist', _I), ('numberofedges', ctypes.c_int)]


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


def _array(d, key, dtype, columns):
    if key not in d or d[key] is None:
        return None
    a = np.ascontiguousarray(np.asarray(d[key], dtype=dtype))
    if a.size == 0:
        return None
    return a.reshape(-1, columns) if columns else a.reshape(len(a), -1)


def _set(io, field, array, keep):
    if array is None:
        return
    keep.append(array)
    ctype = _D if array.dtype == np.float64 else _I
    setattr(io, field, array.ctypes.data_as(ctype))


def _vertices(d, io, keep, dimension):
    vertices = _array(d, 'vertices', np.float64, dimension)
    if vertices is None:
        raise DeltriError(1, "the input has no 'vertices'")
    io.numberofpoints = len(vertices)
    _set(io, 'pointlist', vertices, keep)


def _fill_input(d, io, keep):
    _vertices(d, io, keep, 2)
    attributes = _array(d, 'vertex_attributes', np.float64, None)
    if attributes is not None:
        io.numberofpointattributes = attributes.shape[1]
        _set(io, 'pointattributelist', attributes, keep)
    _set(io, 'pointmarkerlist', _array(d, 'vertex_markers', np.intc, 1), keep)
    segments = _array(d, 'segments', np.intc, 2)
    if segments is not None:
        io.numberofsegments = len(segments)
        _set(io, 'segmentlist', segments, keep)
        _set(io, 'segmentmarkerlist', _array(d, 'segment_markers', np.intc, 1), keep)
    holes = _array(d, 'holes', np.float64, 2)
    if holes is not None:
        io.numberofholes = len(holes)
        _set(io, 'holelist', holes, keep)
    regions = _array(d, 'regions', np.float64, 4)
    if regions is not None:
        io.numberofregions = len(regions)
        _set(io, 'regionlist', regions, keep)
    triangles = _array(d, 'triangles', np.intc, None)
    if triangles is not None:
        io.numberoftriangles = len(triangles)
        io.numberofcorners = triangles.shape[1]
        _set(io, 'trianglelist', triangles, keep)
        attributes = _array(d, 'triangle_attributes', np.float64, None)
        if attributes is not None:
            io.numberoftriangleattributes = attributes.shape[1]
            _set(io, 'triangleattributelist', attributes, keep)
        _set(io, 'trianglearealist', _array(d, 'triangle_max_area', np.float64, 1), keep)


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


def triangulate(d, opts='', size=None):
    """Triangulates the dict d (the `triangle` package's keys: vertices, vertex_markers,
    vertex_attributes, segments, segment_markers, holes, regions, and for 'r' triangles,
    triangle_attributes, triangle_max_area) with Triangle's switches `opts` (no dash); numbering
    is from 0 (z is always added) and nothing is printed (Q). Returns a dict with the same keys
    (and neighbors, edges, edge_markers as the switches ask; with 'v' voronoi_vertices,
    voronoi_edges, voronoi_ray_directions). `size`, if given, is called as
    size(((x0, y0), (x1, y1), (x2, y2)), area) for triangles during refinement: a true result
    means too big, split it. Raises DeltriError on bad input."""
    keep = []
    io_in, io_out, io_vor = _TriangulateIO(), _TriangulateIO(), _TriangulateIO()
    _fill_input(d, io_in, keep)
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
    switches = ('Qz' + opts).encode()
    code = _lib.deltri_triangulate_sized(switches, ctypes.byref(io_in), ctypes.byref(io_out),
                                         ctypes.byref(io_vor), callback, None, ctypes.byref(status))
    if thrown:
        _output(io_out, io_vor if 'v' in opts else None)  # release what was made
        raise thrown[0]
    if code != 0:
        raise DeltriError(code, status.message.decode(errors='replace'))
    result = _output(io_out, io_vor if 'v' in opts else None)
    for key in ('holes', 'regions'):
        if key in d and 'p' in opts and 'r' not in opts:
            result[key] = np.array(d[key], dtype=np.float64)
    return result


def _facets_in(d, io, keep):
    _vertices(d, io, keep, 3)
    _set(io, 'pointmarkerlist', _array(d, 'vertex_markers', np.intc, 1), keep)
    corners, sizes, per_facet, holes, holes_per_facet, markers = [], [], [], [], [], []
    for facet in d.get('facets', []):
        polygons = facet.get('polygons', [])
        per_facet.append(len(polygons))
        for polygon in polygons:
            polygon = np.asarray(polygon, dtype=np.intc).reshape(-1)
            sizes.append(len(polygon))
            corners.extend(polygon.tolist())
        facet_holes = np.asarray(facet.get('holes', []), dtype=np.float64).reshape(-1, 3)
        holes_per_facet.append(len(facet_holes))
        holes.extend(facet_holes.reshape(-1).tolist())
        markers.append(int(facet.get('marker', 0)))
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
    (the subsegments, s x 2) and edge_markers (unless 'B'). Raises DeltriError on bad input."""
    keep = []
    io_in, io_out, status = _Facets(), _Surface(), _Status()
    _facets_in(d, io_in, keep)
    code = _lib.deltri_mesh_surface(('z' + opts).encode(), ctypes.byref(io_in), ctypes.byref(io_out),
                                    ctypes.byref(status))
    if code != 0:
        raise DeltriError(code, status.message.decode(errors='replace'))
    items = [('vertices', io_out.pointlist, io_out.numberofpoints, 3, np.float64),
             ('vertex_markers', io_out.pointmarkerlist, io_out.numberofpoints, 1, np.intc),
             ('triangles', io_out.trianglelist, io_out.numberoftriangles, 3, np.intc),
             ('triangle_attributes', io_out.triangleattributelist, io_out.numberoftriangles, 1, np.float64),
             ('triangle_facets', io_out.trianglefacetlist, io_out.numberoftriangles, 1, np.intc),
             ('edges', io_out.edgelist, io_out.numberofedges, 2, np.intc),
             ('edge_markers', io_out.edgemarkerlist, io_out.numberofedges, 1, np.intc)]
    result = {}
    for key, pointer, count, columns, dtype in items:
        a = _copy(pointer, count, columns, dtype)
        if a is not None:
            result[key] = a.reshape(-1) if key == 'triangle_facets' else a
    _lib.deltri_surface_free(ctypes.byref(io_out))
    return result
