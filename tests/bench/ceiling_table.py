#!/usr/bin/env python3
"""The ceiling table of docs/refinement.md ("Locally optimal Steiner points"), deltri against
Triangle 1.6 on the same inputs (issue 44).

    ceiling_table.py DELTRI TRIANGLE VERIFY CORPUS_DIR [--files a.poly,...] [--extra-input X.poly]
                     [--top 40] [--timeout 300] [--triangle-timeout 60] [--interleaved]

For each input and each program, `-pq<q>Q` runs for q = 34, 35, ... up to --top; each mesh is
checked by VERIFY (deltri_mesh_verify --refined --min-angle q: every triangle at the bound, the
mesh conforming to the input), and the climb stops at the first q not met (Triangle runs on without
end above its ceiling: the timeout stops it). The ceiling is the highest q met. Prints one
Markdown row per input: triangles and wall seconds (the least of --repeat runs) at -q34 and at the
ceiling, the multiples; then per input the figures at --at (40) against -q34, and for the first q
not met what happened (warned, timed out, or the verifier's complaint).
With --interleaved, only deltri's -q34 and --at runs, each mesh checked, then their timed runs
alternating, and one row per input with the multiples (the issue's "under 10x the time and
triangles of the -q34 run").
A benchmark for docs, not a test: nothing is asserted.
"""
import argparse, os, shutil, subprocess, time

from scratch_input import scratch_copy

# The corpus files whose input angles are all 60 degrees or more (the corpus's SOURCES.md).
DEFAULT_FILES = ','.join([
    'tnakaicode__jburkardt-data/triangle_files/airfoil_exterior.poly',
    'tnakaicode__jburkardt-data/poly/bicycle_seat.poly', 'drufat__triangle/double_hex.poly',
    'drufat__triangle/double_hex3.poly', 'tnakaicode__jburkardt-data/poly/p01.poly',
    'tnakaicode__jburkardt-data/poly/p09.poly', 'tnakaicode__jburkardt-data/poly/p14.poly',
    'benjones__fem2D/ring.poly', 'dengwirda__mesh2d/converted/river.poly',
    'drufat__triangle/square_circle_hole.poly'])

ap = argparse.ArgumentParser()
ap.add_argument('deltri'); ap.add_argument('triangle'); ap.add_argument('verify'); ap.add_argument('corpus')
ap.add_argument('--files', default=DEFAULT_FILES)
ap.add_argument('--extra-input', action='append', default=[], help='an input outside the corpus (a path)')
ap.add_argument('--top', type=int, default=45)
ap.add_argument('--timeout', type=float, default=300); ap.add_argument('--triangle-timeout', type=float, default=60)
ap.add_argument('--repeat', type=int, default=3, help='runs per mesh that is met; the least wall time is kept')
ap.add_argument('--at', type=int, default=40, help='a bound whose figures are printed as well (the goal)')
ap.add_argument('--interleaved', action='store_true',
                help='only deltri at -q34 and --at, their runs alternating (the load moves both alike)')
args = ap.parse_args()


def run(program, path, q, timeout):
    """(triangles, seconds, None) when the mesh meets q, else (None, None, why)."""
    d = scratch_copy(path)
    try:
        b = os.path.basename(path)
        start = time.monotonic()
        try:
            r = subprocess.run([program, f'-pq{q}Q', b], cwd=d, capture_output=True, text=True, timeout=timeout)
        except subprocess.TimeoutExpired:
            return None, None, f'timed out after {timeout:.0f} s'
        seconds = time.monotonic() - start
        base = b[:-5] + '.1'
        if r.returncode != 0 or not os.path.exists(os.path.join(d, base + '.ele')):
            return None, None, f'exit {r.returncode}'
        n = int(open(os.path.join(d, base + '.ele')).readline().split()[0])
        v = subprocess.run([args.verify, '--input', b, '--mesh', base, '--refined', '--min-angle', str(q)],
                           cwd=d, capture_output=True, text=True)
        if v.returncode != 0:
            why = (v.stdout + v.stderr).strip().splitlines()
            warned = 'warned' if 'warning' in r.stderr else 'no warning'
            return None, None, f'{n:,} triangles, {warned}, verifier: {why[0][:80] if why else "failed"}'
        for _ in range(args.repeat - 1):
            start = time.monotonic()
            subprocess.run([program, f'-pq{q}Q', b], cwd=d, capture_output=True, timeout=timeout)
            seconds = min(seconds, time.monotonic() - start)
        return n, seconds, None
    finally:
        shutil.rmtree(d)


def climb(program, path, timeout):
    """(the -q34 run, the run at the ceiling, the ceiling, what happened above it, the run at --at)."""
    at34 = run(program, path, 34, timeout)
    if at34[0] is None:
        return at34, None, 33, at34[2], None
    best, ceiling, at = at34, 34, None
    for q in range(35, args.top + 1):
        got = run(program, path, q, timeout)
        if got[0] is None:
            return at34, best, ceiling, f'-q{q}: {got[2]}', at
        best, ceiling = got, q
        at = got if q == args.at else at
    return at34, best, ceiling, '', at


def at_goal(at34, at):
    if at is None or at34[0] is None:
        return f'-q{args.at} not met'
    return f'-q{args.at}: {at[0]:,} / {at[1]:.3f} s = {at[0] / at34[0]:.2f}x / {at[1] / max(at34[1], 1e-3):.1f}x'


def cells(at34, best, ceiling):
    if at34[0] is None:
        return ['-', '<34', '-', '-']
    first = f'{at34[0]:,} / {at34[1]:.3f}'
    if ceiling == 34:
        return [first, '34', '-', '-']
    return [first, str(ceiling), f'{best[0]:,} / {best[1]:.3f}',
            f'{best[0] / at34[0]:.2f}x / {best[1] / max(at34[1], 1e-3):.1f}x']


def interleaved(path):
    """The -q34 and --at meshes checked once, then --repeat more runs of each in turn: the least
    wall times of each, so that a busy spell slows both alike."""
    first = [run(args.deltri, path, q, args.timeout) for q in (34, args.at)]
    if any(r[0] is None for r in first):
        return first
    d = scratch_copy(path)
    try:
        b = os.path.basename(path)
        best = [r[1] for r in first]
        for _ in range(args.repeat):
            for i, q in enumerate((34, args.at)):
                start = time.monotonic()
                subprocess.run([args.deltri, f'-pq{q}Q', b], cwd=d, capture_output=True, timeout=args.timeout)
                best[i] = min(best[i], time.monotonic() - start)
        return [(first[0][0], best[0], None), (first[1][0], best[1], None)]
    finally:
        shutil.rmtree(d)


inputs = [os.path.join(args.corpus, f) for f in args.files.split(',') if f] + args.extra_input
if args.interleaved:
    print(f'| input | -q34 triangles / s | -q{args.at} triangles / s | multiples of -q34 |')
    print('|---|---|---|---|')
    for path in inputs:
        low, high = interleaved(path)
        name = os.path.basename(path)
        if low[0] is None or high[0] is None:
            print(f'| {name} | {low[2] or "met"} | {high[2] or "met"} | - |', flush=True)
            continue
        print(f'| {name} | {low[0]:,} / {low[1]:.3f} | {high[0]:,} / {high[1]:.3f} | '
              f'{high[0] / low[0]:.2f}x / {high[1] / low[1]:.1f}x |', flush=True)
    raise SystemExit(0)
print('| input | deltri -q34 triangles / s | deltri ceiling | at the ceiling: triangles / s | multiples of -q34 '
      '| Triangle -q34 triangles / s | Triangle ceiling | at its ceiling | multiples |')
print('|---|---|---|---|---|---|---|---|---|')
notes = []
for path in inputs:
    ours = climb(args.deltri, path, args.timeout)
    theirs = climb(args.triangle, path, args.triangle_timeout)
    name = os.path.basename(path)
    print('| ' + ' | '.join([name] + cells(*ours[:3]) + cells(*theirs[:3])) + ' |', flush=True)
    notes.append(f'{name}: deltri {at_goal(ours[0], ours[4])}, above its ceiling {ours[3] or "-"}; '
                 f'Triangle above its ceiling {theirs[3] or "-"}')
print()
for n in notes:
    print('* ' + n)
