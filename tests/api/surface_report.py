"""The surface library reports what its mesh is not, as the command line warns of it (issue 47):
merged points, facets left empty, a Steiner budget that ended the run, and the triangles that miss
the bounds then. Through the Python module (on the C struct deltri_surface). Facts computed here:
the pairs of input vertices with equal coordinates (the later one and the first one), the facet
with a hole point and no inner loop, and the triangles of the returned arrays below 30 degrees.
    surface_report.py
"""
import math
import sys

import numpy as np

import deltri


def fail(msg):
    print("FAIL:", msg)
    sys.exit(1)


def box(sz=1.0):
    v = [(x, y, z * sz) for z in (0, 1) for y in (0, 1) for x in (0, 1)]
    faces = [[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [1, 3, 7, 5], [3, 2, 6, 7], [2, 0, 4, 6]]
    return v, faces


def facets(faces, holes=None):
    holes = holes or {}
    return [{'polygons': [f], 'holes': np.array(holes.get(k, []), dtype=float).reshape(-1, 3)} for k, f in enumerate(faces)]


def smallest_angle(p, q, r):
    def ang(o, a, b):
        u, w = a - o, b - o
        return math.degrees(math.atan2(np.linalg.norm(np.cross(u, w)), np.dot(u, w)))
    return min(ang(p, q, r), ang(q, r, p), ang(r, p, q))


# A cube whose top facet names copies of its corner points.
v, faces = box()
v += v[4:8]
faces[1] = [8, 9, 11, 10]
out = deltri.mesh_surface({'vertices': np.array(v), 'facets': facets(faces)}, 'pq30')
first = {}
want = []
for i, p in enumerate(v):
    if p in first:
        want.append([i, first[p]])
    else:
        first[p] = i
got = out.get('merged_vertices')
if got is None or got.tolist() != want:
    fail(f"merged_vertices {got} , expected {want}")
if out['budget_reached'] or out['rounds_exhausted'] or out.get('emptied_facets') is not None:
    fail(f"a plain cube reported as stopped or emptied: {out}")

# A hole point in the top facet, which has no inner loop: that facet is carved away.
v, faces = box()
out = deltri.mesh_surface({'vertices': np.array(v), 'facets': facets(faces, {1: [(0.5, 0.5, 1.0)]})}, 'p')
got = out.get('emptied_facets')
if got is None or got.tolist() != [1] or 'merged_vertices' in out:
    fail(f"emptied_facets {got}, expected [1]")

# A 1e-7-thick box at -pq30S500: the budget ends the run, and the misses are counted.
v, faces = box(1e-7)
out = deltri.mesh_surface({'vertices': np.array(v), 'facets': facets(faces)}, 'pq30S500')
pts, tris = out['vertices'], out['triangles']
below = sum(smallest_angle(pts[a], pts[b], pts[c]) < 30.0 for a, b, c in tris)
if not out['budget_reached'] or out['rounds_exhausted']:
    fail(f"the -S budget's stop not reported: {out['budget_reached']}, {out['rounds_exhausted']}")
if out['triangles_below_angle'] != below or below == 0:
    fail(f"triangles_below_angle {out['triangles_below_angle']}, the arrays have {below} below 30 degrees")
print(f"ok: merged {want}; emptied [1]; -S500 budget reached, {below} of {len(tris)} triangles below 30 degrees")
