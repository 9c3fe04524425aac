"""The pyNastran gear at -pq30a20, -pq30a2 and -pq30a0.02 (issue 42): the facets agree on their
shared segments within the rounds, and no triangle is below what the input's smallest corner forces.

Recomputed here from the input and the written .node/.ele with numpy, none of deltri's numbers:
- the run converges: exit 0 and no warning (neither the round cap's nor the budget's -YY pass);
- the surface is closed and conforming: the gear is a closed solid, so every edge lies in exactly
  two triangles (a cut that one facet holds and its neighbour does not leaves edges in one), no two
  points coincide, and the triangles' areas sum to the facets' areas;
- every angle is at least the input's smallest corner theta (7.083 degrees), to the rounding of the
  written coordinates: shells a factor 2 apart around a corner would leave, beyond the corner
  triangle, the triangle joining the shell vertices at r on both sides to the next at 2r on one,
  whose angle at the far vertex is just under theta (6.977, the `rung_floor` below; Triangle 1.6
  leaves it at a 7.083-degree corner of a PSLG at -q30); nothing forces it, and it must be gone;
- every triangle below 30 degrees has a vertex within reach of a corner under 30 degrees: within
  the longest input segment at that corner (the shells lie on its segments);
- no angle above 120 degrees (a triangle with all angles at least 30 has none larger; gmsh meshes
  the gear at 129).
usage: gear_quality.py DELTRI SOURCE_DIR AREA
"""
import math
import shutil
import subprocess
import sys
import tempfile

import numpy as np


def table(path):
    rows = [line.split('#')[0].split() for line in open(path)]
    return [r for r in rows if r]


def angles(p, tri):
    a, b, c = p[tri[:, 0]], p[tri[:, 1]], p[tri[:, 2]]

    def at(o, u, v):
        u, v = u - o, v - o
        return np.degrees(np.arctan2(np.linalg.norm(np.cross(u, v), axis=1), (u * v).sum(axis=1)))

    return np.stack([at(a, b, c), at(b, c, a), at(c, a, b)], axis=1)


def rung_floor(theta_deg):
    """The smallest angle of the triangle with corners at r on one side of a wedge and r and 2r on the other."""
    t = math.radians(theta_deg)
    p = np.array([[[1.0, 0.0, 0.0], [math.cos(t), math.sin(t), 0.0], [2 * math.cos(t), 2 * math.sin(t), 0.0]]])
    return angles(p[0], np.array([[0, 1, 2]])).min()


def main():
    deltri, src, area = sys.argv[1], sys.argv[2], sys.argv[3]
    work = tempfile.mkdtemp()
    for ext in ('smesh', 'node'):
        shutil.copy(f'{src}/tests/surface/inputs/pynastran_gear.{ext}', work)
    run = subprocess.run([deltri, f'-pq30a{area}', 'pynastran_gear.smesh'], cwd=work, capture_output=True, text=True,
                         timeout=600)
    if run.returncode != 0 or 'warning' in run.stderr:
        sys.exit(f'deltri exited {run.returncode}: {run.stderr}')

    rows = table(f'{work}/pynastran_gear.node')
    base = int(rows[1][0])
    inp = np.array([[float(x) for x in r[1:4]] for r in rows[1:1 + int(rows[0][0])]])
    rows = table(f'{work}/pynastran_gear.smesh')
    facets = np.array([[int(x) - base for x in r[1:4]] for r in rows[2:2 + int(rows[1][0])]])
    corner = angles(inp, facets)
    theta = corner.min()
    floor = rung_floor(theta)
    # Corners under 30 degrees, and the longest input segment at each.
    reach = {}
    for f, tri in enumerate(facets):
        for i in range(3):
            if corner[f, i] < 30.0:
                v = tri[i]
                longest = max(np.linalg.norm(inp[tri[j]] - inp[v]) for j in range(3) if j != i)
                reach[v] = max(reach.get(v, 0.0), longest)
    input_area = 0.5 * np.linalg.norm(np.cross(inp[facets[:, 1]] - inp[facets[:, 0]],
                                               inp[facets[:, 2]] - inp[facets[:, 0]]), axis=1).sum()

    rows = table(f'{work}/pynastran_gear.1.node')
    base = int(rows[1][0])
    p = np.array([[float(x) for x in r[1:4]] for r in rows[1:1 + int(rows[0][0])]])
    rows = table(f'{work}/pynastran_gear.1.ele')
    tri = np.array([[int(x) - base for x in r[1:4]] for r in rows[1:1 + int(rows[0][0])]])

    faults = []
    edges = np.sort(np.concatenate([tri[:, [0, 1]], tri[:, [1, 2]], tri[:, [2, 0]]]), axis=1)
    _, uses = np.unique(edges, axis=0, return_counts=True)
    if not (uses == 2).all():
        faults.append(f'{(uses != 2).sum()} edges not in exactly two triangles')
    if len(np.unique(p[np.unique(tri)], axis=0)) != len(np.unique(tri)):
        faults.append('two points of triangles coincide')
    out_area = 0.5 * np.linalg.norm(np.cross(p[tri[:, 1]] - p[tri[:, 0]], p[tri[:, 2]] - p[tri[:, 0]]), axis=1)
    if abs(out_area.sum() - input_area) > 1e-9 * input_area:
        faults.append(f'area {out_area.sum()} against the facets\' {input_area}')
    if out_area.max() > float(area) * (1 + 1e-9):
        faults.append(f'a triangle of area {out_area.max()} above -a{area}')
    ang = angles(p, tri)
    smallest, largest = ang.min(axis=1), ang.max(axis=1)
    if smallest.min() < theta - 1e-6:  # the written coordinates are rounded
        faults.append(f'smallest angle {smallest.min():.4f} below the {theta:.4f}-degree corner '
                      f'(the 2r rung triangle would have {floor:.4f})')
    if largest.max() > 120.0 + 1e-6:
        faults.append(f'largest angle {largest.max():.4f} above 120')
    apex = np.array(sorted(reach))
    radius = np.array([reach[v] for v in apex])
    unexplained = 0
    for t in np.nonzero(smallest < 30.0 - 1e-9)[0]:
        d = np.linalg.norm(p[tri[t]][:, None, :] - inp[apex][None, :, :], axis=2).min(axis=0)
        unexplained += not (d <= radius * (1 + 1e-9)).any()
    if unexplained:
        faults.append(f'{unexplained} triangles below 30 degrees away from every corner under 30')
    print(f'-pq30a{area}: {len(tri)} triangles, smallest {smallest.min():.4f} (corner {theta:.4f}, floor {floor:.4f}), '
          f'largest {largest.max():.4f}, {(smallest < 30.0 - 1e-9).sum()} below 30 at small corners')
    if faults:
        sys.exit('; '.join(faults))
    shutil.rmtree(work)


main()
