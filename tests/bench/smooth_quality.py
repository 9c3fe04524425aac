#!/usr/bin/env python3
"""--smooth before and after on a list of .poly files (docs/refinement.md, "Mesh improvement (--smooth)").

usage: smooth_quality.py DELTRI SWITCHES FILE.poly... [--check MESHCHECK]

For each file: deltri SWITCHES and deltri SWITCHES --smooth -C in scratch folders; from the written
.node/.ele alone, the triangles, the smallest angle, the mean of the smallest angles per triangle and
the histogram of radius-edge ratios (circumradius over shortest edge), before and after. With
--check, the independent checker also runs on both meshes with the -q angle of SWITCHES.
"""
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile

BINS = [0.6, 0.65, 0.7, 0.8, 0.9, 1.0]  # radius-edge ratio bin edges; 1/sqrt(3) is the least there is


def rows(path):
    with open(path) as f:
        for line in f:
            words = line.split('#')[0].split()
            if words:
                yield words


def triangles(base):
    it = rows(base + '.node')
    n = int(next(it)[0])
    pts = {}
    for _ in range(n):
        w = next(it)
        pts[w[0]] = (float(w[1]), float(w[2]))
    it = rows(base + '.ele')
    m = int(next(it)[0])
    return [tuple(pts[i] for i in next(it)[1:4]) for _ in range(m)]


def angle(a, b, c):
    ux, uy, vx, vy = b[0] - a[0], b[1] - a[1], c[0] - a[0], c[1] - a[1]
    return math.degrees(math.atan2(abs(ux * vy - uy * vx), ux * vx + uy * vy))


def figures(base):
    smallest, hist = [], [0] * (len(BINS) + 1)
    for a, b, c in triangles(base):
        smallest.append(min(angle(a, b, c), angle(b, c, a), angle(c, a, b)))
        la, lb, lc = math.dist(b, c), math.dist(c, a), math.dist(a, b)
        area = 0.5 * abs((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]))
        ratio = la * lb * lc / (4 * area) / min(la, lb, lc)
        hist[sum(ratio >= e for e in BINS)] += 1
    return len(smallest), min(smallest), sum(smallest) / len(smallest), hist


def run(deltri, switches, poly, extra, check, angle_bound):
    with tempfile.TemporaryDirectory() as tmp:
        local = os.path.join(tmp, os.path.basename(poly))
        shutil.copy(poly, local)
        subprocess.run([deltri, '-Q', switches] + extra + [local], check=True)
        base = local[:-5] + '.1'
        checked = 'not run'
        if check:
            cmd = [sys.executable, check, '--input', local, '--mesh', base] + (['--min-angle', angle_bound] if angle_bound else [])
            checked = 'ok' if subprocess.run(cmd, stdout=subprocess.DEVNULL).returncode == 0 else 'FAILED'
        return figures(base), checked


def main(argv):
    check = None
    if '--check' in argv:
        k = argv.index('--check')
        check = argv[k + 1]
        del argv[k:k + 2]
    deltri, switches, files = argv[1], argv[2], argv[3:]
    q = re.search(r'q([0-9.]+)', switches)
    angle_bound = q.group(1) if q else None
    labels = ['<0.6'] + ['%g-%g' % (BINS[i], BINS[i + 1]) for i in range(len(BINS) - 1)] + ['>=1']
    print('| input | triangles | smallest angle before -> after | mean smallest angle before -> after | '
          'radius-edge histogram (%s) before / after | checker |' % ', '.join(labels))
    print('|---|---|---|---|---|---|')
    lowered = 0
    for poly in files:
        (n0, min0, mean0, h0), c0 = run(deltri, switches, poly, [], check, angle_bound)
        (n1, min1, mean1, h1), c1 = run(deltri, switches, poly, ['--smooth', '-C'], check, angle_bound)
        lowered += min1 < min0 or n1 != n0
        print('| %s | %d | %.3f -> %.3f | %.3f -> %.3f | %s / %s | %s, %s |' % (
            os.path.basename(poly), n0, min0, min1, mean0, mean1, ' '.join(map(str, h0)), ' '.join(map(str, h1)), c0, c1))
    return 1 if lowered else 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
