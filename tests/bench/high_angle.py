#!/usr/bin/env python3
"""Angle bounds above 34 degrees against the 34-degree run, per corpus file (issue 16).

    high_angle.py DELTRI CORPUS_DIR [--angles 34,36,40] [--timeout 300] [--files a.poly,b.poly]

For each .poly under CORPUS_DIR (with its .node beside it when the .poly has no vertices) runs
`DELTRI -pq<angle>V` for every angle and prints triangles, wall seconds, peak RSS and whether the
run warned, then the multiples of the higher-angle runs over the first angle's (the guard's promise,
docs/refinement.md "Two stages above 34 degrees": at most about three times the vertices at the peak
and the second stage's time). A benchmark for docs, not a test: nothing is asserted.
"""
import argparse, glob, os, re, shutil, subprocess

from scratch_input import scratch_copy

ap = argparse.ArgumentParser()
ap.add_argument('deltri'); ap.add_argument('corpus')
ap.add_argument('--angles', default='34,36,40'); ap.add_argument('--timeout', type=float, default=300)
ap.add_argument('--files', default='')
args = ap.parse_args()
angles = args.angles.split(',')
files = sorted(glob.glob(os.path.join(args.corpus, '**', '*.poly'), recursive=True))
if args.files:
    files = [f for f in files if os.path.relpath(f, args.corpus) in args.files.split(',')]


def run(path, angle):
    d = scratch_copy(path)
    try:
        b = os.path.basename(path)
        cmd = ['/usr/bin/time', '-f', 'TIME %e %M', args.deltri, f'-pq{angle}V', b]
        try:
            r = subprocess.run(cmd, cwd=d, capture_output=True, text=True, timeout=args.timeout)
        except subprocess.TimeoutExpired:
            return None
        m = re.search(r'TIME ([0-9.]+) (\d+)', r.stderr)
        tri = re.search(r'Mesh triangles: (\d+)', r.stdout + r.stderr)
        warned = 'warning' in r.stderr
        return (int(tri.group(1)) if tri else 0, float(m.group(1)), int(m.group(2)) / 1024.0, warned, r.returncode)
    finally:
        shutil.rmtree(d)


worst = {a: [0.0, 0.0, 0.0] for a in angles[1:]}
for f in files:
    rel = os.path.relpath(f, args.corpus)
    res = {a: run(f, a) for a in angles}
    cells = []
    for a in angles:
        r = res[a]
        cells.append(f'q{a}: timeout' if r is None else
                     f'q{a}: {r[0]} tri {r[1]:.2f} s {r[2]:.0f} MB{" W" if r[3] else ""}{" rc" + str(r[4]) if r[4] else ""}')
    base = res[angles[0]]
    for a in angles[1:]:
        r = res[a]
        if base and r and base[0] > 0:
            ratios = (r[0] / base[0], r[1] / max(base[1], 0.01), r[2] / max(base[2], 1.0))
            worst[a] = [max(x, y) for x, y in zip(worst[a], ratios)]
            cells.append(f'x{a}/{angles[0]}: {ratios[0]:.2f} {ratios[1]:.2f} {ratios[2]:.2f}')
    print(rel[:50].ljust(50), '  '.join(cells), flush=True)
for a, w in worst.items():
    print(f'largest multiple q{a} over q{angles[0]}: triangles {w[0]:.2f}  time {w[1]:.2f}  memory {w[2]:.2f}')
