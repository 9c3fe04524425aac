#!/usr/bin/env python3
"""--max-angle on the corpus against -q alone (issue 44), for docs/refinement.md's table "Largest-angle
bound". A benchmark for docs, not a test: nothing is asserted.

    max_angle_corpus.py DELTRI CORPUS_DIR... [--flags=-pq] [--angles 90,100] [--timeout 20] [--jobs 2]

For each .poly under each CORPUS_DIR runs `DELTRI FLAGS --json` alone and with --max-angle=A for
every A (in a scratch directory, killed after TIMEOUT seconds) and prints, per file and in total,
the triangles, those above A, those above A not forced by the input (the JSON report's counts,
which tests/refine/max_angle.py checks against an exact count of the written mesh) and whether the
run met A everywhere the input allows, and per A the slowest run (the JSON's seconds before
writing)."""
import argparse
import concurrent.futures
import glob
import json
import os
import shutil
import subprocess

from scratch_input import scratch_copy

ap = argparse.ArgumentParser()
ap.add_argument('deltri')
ap.add_argument('corpus', nargs='+')
ap.add_argument('--flags', default='-pq')
ap.add_argument('--angles', default='90,100')
ap.add_argument('--timeout', type=float, default=20)
ap.add_argument('--jobs', type=int, default=2)
ap.add_argument('--quiet', action='store_true')
args = ap.parse_args()
deltri = os.path.abspath(args.deltri)
files = sorted(f for c in args.corpus for f in glob.glob(os.path.join(c, '**', '*.poly'), recursive=True))
modes = [None] + [float(a) for a in args.angles.split(',')]


def run(path, angle):
    d = scratch_copy(path)
    try:
        cmd = [deltri] + args.flags.split() + ['-Q', '--json=report.json']
        if angle is not None:
            cmd.append(f'--max-angle={angle:g}')
        cmd.append(os.path.basename(path))
        try:
            subprocess.run(cmd, cwd=d, timeout=args.timeout, capture_output=True)
        except subprocess.TimeoutExpired:
            return 'timeout'
        try:
            with open(os.path.join(d, 'report.json')) as f:
                r = json.load(f)
        except (OSError, ValueError):
            return 'failed'
        if r.get('exit_status') not in (0, 3) or not r.get('mesh', {}).get('triangles'):
            return 'failed'
        q = r['quality']
        causes = q['missing_bounds_by_cause']
        return {'triangles': r['mesh']['triangles'], 'above': q.get('triangles_above_max_angle', 0),
                'not_forced': q['triangles_missing_bounds_not_forced_by_input'],
                'large_input': causes.get('large_input_angle', 0),
                'seconds': r.get('seconds', {}).get('total_before_writing', 0.0)}
    finally:
        shutil.rmtree(d, ignore_errors=True)


with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
    jobs = {(f, a): pool.submit(run, f, a) for f in files for a in modes}
    results = {k: v.result() for k, v in jobs.items()}

def name(a):
    return 'alone' if a is None else f'A={a:g}'

for f in files:
    if args.quiet:
        break
    cells = []
    for a in modes:
        r = results[(f, a)]
        cells.append(f'{name(a)}: {r}' if isinstance(r, str) else
                     f"{name(a)}: {r['triangles']} tri, {r['above']} above ({r['not_forced']} unforced)")
    print(os.path.relpath(f), ' | '.join(cells))

alone = {f for f in files if isinstance(results[(f, None)], dict)}
print(f'files {len(files)}, meshed alone {len(alone)}')
for a in modes[1:]:
    ok = [f for f in files if isinstance(results[(f, a)], dict)]
    met = [f for f in ok if results[(f, a)]['not_forced'] == 0]
    both = [f for f in ok if f in alone]
    tri = sum(results[(f, a)]['triangles'] for f in both)
    tri0 = sum(results[(f, None)]['triangles'] for f in both)
    above = sum(results[(f, a)]['above'] for f in ok)
    forced = sum(results[(f, a)]['large_input'] for f in ok)
    met0 = [f for f in met if results[(f, None)] != 'timeout']
    print(f'{name(a)}: meshed {len(ok)} ({sum(results[(f, a)] == "timeout" for f in files)} over '
          f'{args.timeout:g} s), every triangle at A or forced {len(met)}, triangles {tri} vs {tri0} alone on '
          f'those {len(both)} ({tri / max(tri0, 1):.2f}x), above A {above} ({forced} between input segments)')
    print('  not met:', ' '.join(os.path.basename(f) for f in ok if f not in met))
    if ok:
        slowest = max(ok, key=lambda f: results[(f, a)]['seconds'])
        print(f"  slowest: {os.path.relpath(slowest)}, {results[(slowest, a)]['seconds']:.2f} s before writing")
