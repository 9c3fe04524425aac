"""The background size field (--size-field) and a size function (the Python module's size=), each on
box.poly (a 3 x 3 square with a 1 x 1 hole) with the wanted edge length h = 0.05 + 0.05 x:
every triangle must meet the documented rule (area at most sqrt(3)/4 h^2, h at its centroid) and
the count must be within 2x of the smallest count that could meet it, the integral of
4 / (sqrt(3) h^2) over the domain, computed here in closed form.
    DELTRI_LIBRARY=... PYTHONPATH=src/api/python size_field.py DELTRI SOURCE_DIR"""
import math
import os
import shutil
import subprocess
import sys
import tempfile

import numpy as np

failures = []


def h(x):
    return 0.05 + 0.05 * x


# The domain is [0,3]^2 without [1,2]^2: 3 high for x outside [1,2], 2 inside. With h = 0.05 (1 + x),
# the integral of 4 / (sqrt(3) h^2) is 4 / (sqrt(3) 0.05^2) (int_0^3 3/(1+x)^2 dx - int_1^2 1/(1+x)^2 dx).
LOWER_BOUND = 4.0 / (math.sqrt(3.0) * 0.05 ** 2) * (3.0 * (1.0 - 1.0 / 4.0) - (1.0 / 2.0 - 1.0 / 3.0))


def lines(path):
    return [l for l in (raw.split('#')[0].split() for raw in open(path)) if l]


def judge(label, vertices, triangles):
    p = vertices[triangles[:, :3]]
    area = 0.5 * ((p[:, 1, 0] - p[:, 0, 0]) * (p[:, 2, 1] - p[:, 0, 1]) - (p[:, 1, 1] - p[:, 0, 1]) * (p[:, 2, 0] - p[:, 0, 0]))
    bound = math.sqrt(3.0) / 4.0 * h(p[:, :, 0].mean(axis=1)) ** 2
    worst = (area / bound).max()
    n = len(triangles)
    ok_rule = worst <= 1.0 + 1e-9
    ok_count = n <= 2.0 * LOWER_BOUND
    ok_area = math.isclose(area.sum(), 8.0, rel_tol=1e-9)
    edges = np.max([np.hypot(*(p[:, (k + 1) % 3] - p[:, k]).T) for k in range(3)], axis=0)
    longest = (edges / h(p[:, :, 0].mean(axis=1))).max()
    print('%s %s: %d triangles, %.2f times the lower bound %.0f; largest area / bound %.4f; longest edge / h %.2f' %
          ('ok  ' if ok_rule and ok_count and ok_area else 'FAIL', label, n, n / LOWER_BOUND, LOWER_BOUND, worst, longest))
    if not (ok_rule and ok_count and ok_area):
        failures.append(label)


def main():
    deltri, source = sys.argv[1:3]
    work = tempfile.mkdtemp()
    try:
        shutil.copy(os.path.join(source, 'data', 'box.poly'), work)
        for ext in ('node', 'ele'):
            shutil.copy(os.path.join(source, 'tests', 'api', 'inputs', 'size_background.' + ext), work)
        subprocess.run([deltri, '-pq30Q', '--size-field=size_background.node', 'box.poly'], cwd=work, check=True)
        node, ele = lines(os.path.join(work, 'box.1.node')), lines(os.path.join(work, 'box.1.ele'))
        vertices = np.array([[float(f[1]), float(f[2])] for f in node[1:]])
        triangles = np.array([[int(x) - 1 for x in f[1:4]] for f in ele[1:]])
        judge('--size-field=size_background.node -pq30', vertices, triangles)

        import deltri as module
        box = {'vertices': vertices[:8], 'segments': [[0, 1], [1, 2], [2, 3], [3, 0], [4, 5], [5, 6], [6, 7], [7, 4]],
               'holes': [[1.5, 1.5]]}

        def too_big(corners, area):
            x = (corners[0][0] + corners[1][0] + corners[2][0]) / 3.0
            return area > math.sqrt(3.0) / 4.0 * h(x) ** 2
        m = module.triangulate(box, 'pq30', size=too_big)
        judge('size function (Python) -pq30', m['vertices'], m['triangles'])
        m = module.triangulate(box, 'p', size=too_big)
        judge('size function (Python) -p', m['vertices'], m['triangles'])
    finally:
        shutil.rmtree(work)
    sys.exit(1 if failures else 0)


main()
