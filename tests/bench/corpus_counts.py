#!/usr/bin/env python3
"""Triangle counts of deltri on a corpus of .poly files, next to reference counts.

    corpus_counts.py DELTRI CORPUS_DIR REFERENCE.md [--modes q30,q33,q30a] [--extra "--queue=ratio"]

REFERENCE.md is a Markdown table with rows `| dir/file.poly | A | -pq30 | -pq33 | -pq30aA |`
(the layout of triangle-reference-counts.md in the shared notes; A is the area used for q30a).
Rows whose reference is not a number, and files that are missing, are skipped. Prints one line per
file and a total per mode; used for docs/refinement.md (not a test: nothing is asserted).
"""
import argparse, os, re, shutil, subprocess

from scratch_input import scratch_copy

ap = argparse.ArgumentParser()
ap.add_argument('deltri'); ap.add_argument('corpus'); ap.add_argument('reference')
ap.add_argument('--modes', default='q30,q33,q30a'); ap.add_argument('--extra', default='')
ap.add_argument('--skip', default='VVingerfly__Triangulation/test.poly')
args = ap.parse_args()
modes = args.modes.split(',')
rows = []
for line in open(args.reference):
    m = re.match(r'\| (\S+\.poly) \| ([0-9.]+) \| (\S+) \| (\S+) \| (\S+) \|', line)
    if m: rows.append(m.groups())
total = {k: [0, 0] for k in modes}
for f, area, c30, c33, c30a in rows:
    path = os.path.join(args.corpus, f)
    if f in args.skip.split(',') or not os.path.exists(path): continue
    ref = {'q30': c30, 'q33': c33, 'q30a': c30a}
    out = [f[:58].ljust(58)]
    for k in modes:
        if not ref[k].isdigit(): continue
        sw = '-p' + {'q30': 'q30', 'q33': 'q33', 'q30a': 'q30a' + area}[k] + 'Q'
        d = scratch_copy(path)
        try:
            b = os.path.basename(f)
            cmd = [args.deltri, sw] + args.extra.split() + [b]
            r = subprocess.run(cmd, cwd=d, capture_output=True, text=True, timeout=600)
            ele = os.path.join(d, b[:-5] + '.1.ele')
            n = int(open(ele).readline().split()[0]) if r.returncode == 0 and os.path.exists(ele) else 0
        finally:
            shutil.rmtree(d)
        total[k][0] += n; total[k][1] += int(ref[k])
        out.append(f'{k}: {n}/{ref[k]}')
    print('  '.join(out), flush=True)
for k in modes:
    d, t = total[k]
    print(f'total {k}: deltri {d}  reference {t}  ratio {d / max(t, 1):.3f}')
