#!/usr/bin/env python3
"""Triangle counts of deltri against Triangle 1.6 at equal -q on every corpus .poly (issue 44,
"at -q34 the total over the corpus no more than Triangle's, no file above 1.05x at -q33").

    counts_vs_triangle.py DELTRI TRIANGLE CORPUS_DIR [--angles 33,34] [--timeout 60] [--extra="--steiner=optimal"]

Both programs run `-pq<angle>Q` on a scratch copy of each file; a file counts towards an angle's
totals only when both programs gave a mesh within the timeout. Prints one line per file (counts
and ratio, `>1.05` marked) and per angle the totals, their ratio and the files above 1.05x.
A benchmark for docs/refinement.md, not a test: nothing is asserted.
"""
import argparse, glob, os, shutil, subprocess

from scratch_input import scratch_copy

ap = argparse.ArgumentParser()
ap.add_argument('deltri'); ap.add_argument('triangle'); ap.add_argument('corpus')
ap.add_argument('--angles', default='33,34'); ap.add_argument('--timeout', type=float, default=60)
ap.add_argument('--extra', default='')
args = ap.parse_args()
angles = args.angles.split(',')
files = sorted(glob.glob(os.path.join(args.corpus, '**', '*.poly'), recursive=True))


def count(program, path, angle, extra):
    d = scratch_copy(path)
    try:
        b = os.path.basename(path)
        try:
            r = subprocess.run([program, f'-pq{angle}Q'] + extra + [b], cwd=d, capture_output=True,
                               text=True, timeout=args.timeout)
        except subprocess.TimeoutExpired:
            return None
        ele = os.path.join(d, b[:-5] + '.1.ele')
        if r.returncode != 0 or not os.path.exists(ele):
            return None
        n = int(open(ele).readline().split()[0])
        return n if n > 0 else None
    finally:
        shutil.rmtree(d)


totals = {a: [0, 0, 0, []] for a in angles}
for path in files:
    name = os.path.relpath(path, args.corpus)
    cells = [name[:60].ljust(60)]
    for a in angles:
        ours = count(args.deltri, path, a, args.extra.split())
        theirs = count(args.triangle, path, a, [])
        if ours is None or theirs is None:
            cells.append(f'q{a}: {ours} / {theirs}')
            continue
        ratio = ours / theirs
        t = totals[a]
        t[0] += ours; t[1] += theirs; t[2] += 1
        if ratio > 1.05:
            t[3].append(f'{name} {ours}/{theirs}')
        cells.append(f'q{a}: {ours} / {theirs} = {ratio:.3f}' + (' >1.05' if ratio > 1.05 else ''))
    print('  '.join(cells), flush=True)
for a in angles:
    ours, theirs, n, above = totals[a]
    print(f'-pq{a}: {n} files, deltri {ours:,} Triangle {theirs:,} = {ours / max(theirs, 1):.3f}x; '
          f'above 1.05x: {len(above)}' + ('' if not above else ' (' + '; '.join(above) + ')'))
