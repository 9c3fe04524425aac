#!/usr/bin/env python3
"""Smallest angles of deltri against another program (Triangle 1.6) under -Y and -YY.

    y_angles.py DELTRI OTHER CORPUS_DIR REFERENCE.md [--modes Yq,YYq,Yq30a,YYq33] [--jobs 2]

Runs both programs on every .poly file under CORPUS_DIR with -pYq, -pYYq, -pYq30a<A> and -pYYq33
(A: the area of REFERENCE.md's row for the file, as corpus_counts.py uses it; files without one
skip the area mode) and computes every triangle's smallest angle from the written .node/.ele files.
A run is a *loser* when deltri's smallest angle is below both the other program's and the -q angle
(20 for a bare -q), a *winner* the other way round. Prints one line per run, the losers, and per
mode the counts of losers, winners and the rest, deltri's triangle count and its "miss" count (the
warning's number of triangles missing the bounds), next to the other program's count. Used for
docs/refinement.md ("-Y, -YY"); not a test: nothing is asserted, and the other program is not part
of the repository.
"""
import argparse, collections, concurrent.futures, glob, os, re, shutil, subprocess

from scratch_input import scratch_copy
import numpy as np

ap = argparse.ArgumentParser()
ap.add_argument('deltri'); ap.add_argument('other'); ap.add_argument('corpus'); ap.add_argument('reference')
ap.add_argument('--modes', default='Yq,YYq,Yq30a,YYq33'); ap.add_argument('--jobs', type=int, default=2)
ap.add_argument('--skip', default='VVingerfly__Triangulation/test.poly')
args = ap.parse_args()

areas = {}
for line in open(args.reference):
    m = re.match(r'\| (\S+\.poly) \| ([0-9.]+) \|', line)
    if m: areas[m.group(1)] = m.group(2)


def rows_of(path):
    with open(path) as fh:
        return [r for r in (l.split('#')[0].split() for l in fh) if r]


def smallest_angle(directory, base):
    """The smallest angle in degrees of the mesh base.1.node/.ele, and its triangle count."""
    node, ele = os.path.join(directory, base + '.1.node'), os.path.join(directory, base + '.1.ele')
    if not os.path.exists(ele): return None, 0
    nodes, eles = rows_of(node), rows_of(ele)
    n, m = int(nodes[0][0]), int(eles[0][0])
    if m == 0: return None, 0
    index = {int(r[0]): i for i, r in enumerate(nodes[1:n + 1])}
    points = np.array([[float(r[1]), float(r[2])] for r in nodes[1:n + 1]])
    corners = np.array([[index[int(x)] for x in r[1:4]] for r in eles[1:m + 1]])
    a, b, c = (points[corners[:, k]] for k in range(3))

    def angle(p, q, r):
        u, v = q - p, r - p
        return np.degrees(np.arctan2(np.abs(u[:, 0] * v[:, 1] - u[:, 1] * v[:, 0]), (u * v).sum(1)))
    return float(np.minimum(np.minimum(angle(a, b, c), angle(b, c, a)), angle(c, a, b)).min()), m


def run(program, path, switches):
    d = scratch_copy(path)
    try:
        name = os.path.basename(path)
        r = subprocess.run(['timeout', '300', program, switches, name], cwd=d, capture_output=True, text=True)
        miss = re.search(r'(\d+) triangles miss', r.stderr)
        return smallest_angle(d, name[:-5]) + (int(miss.group(1)) if miss else 0,)
    finally:
        shutil.rmtree(d)


def job(path, mode):
    rel = os.path.relpath(path, args.corpus)
    if mode.endswith('a'):
        if rel not in areas: return None
        switches = '-p' + mode + areas[rel] + 'Q'
    else:
        switches = '-p' + mode + 'Q'
    return rel, mode, switches, run(args.deltri, path, switches), run(args.other, path, switches)


files = sorted(f for f in glob.glob(os.path.join(args.corpus, '**', '*.poly'), recursive=True)
               if os.path.relpath(f, args.corpus) not in args.skip.split(','))
jobs = [(f, mode) for f in files for mode in args.modes.split(',')]
tally = collections.defaultdict(lambda: collections.Counter())
losers = []
with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
    for result in pool.map(lambda j: job(*j), jobs):
        if result is None: continue
        rel, mode, switches, (da, dn, dmiss), (oa, on, _) = result
        print(f'{rel[:60]:60} {switches:16} deltri {da if da is None else round(da, 4)!s:>8} n={dn:<7} '
              f'miss={dmiss:<6} | other {oa if oa is None else round(oa, 4)!s:>8} n={on}', flush=True)
        if da is None or oa is None: continue
        q = re.search(r'q(\d+)', switches)
        bound = float(q.group(1)) if q else 20.0
        t = tally[mode]
        t['runs'] += 1; t['deltri triangles'] += dn; t['other triangles'] += on; t['deltri misses'] += dmiss
        if da < min(oa, bound) - 1e-3:
            t['losers'] += 1; losers.append((rel, switches, da, oa))
        elif oa < min(da, bound) - 1e-3:
            t['winners'] += 1
print('losers (deltri, other):')
for rel, switches, da, oa in losers: print(f'  {rel} {switches} {da:.4f} {oa:.4f}')
for mode, t in tally.items():
    print(f'-p{mode}: {t["losers"]} losers, {t["winners"]} winners of {t["runs"]}; triangles {t["deltri triangles"]} '
          f'(other {t["other triangles"]}), deltri misses {t["deltri misses"]}')
