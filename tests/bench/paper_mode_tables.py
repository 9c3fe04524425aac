#!/usr/bin/env python3
"""The tables of docs/refinement.md for the paper's modes, from today's binary (issue 42: the docs must
show what the program does, not what an older one did). Not a test; it needs the shared corpus.

    paper_mode_tables.py DELTRI CORPUS_DIR [--table lopping|limits]

lopping: --corner-lopping against the Terminator at -pq20 and -pq30 (triangles, angles under q over
         every angle of every triangle, shortest edge over the input's shortest segment) on the
         generated inputs of tests/refine/corner_lopping.py and the corpus files below.
limits:  Ruppert's and Chew's algorithms at -pq30, -pq33 and -pq34 on every 2-D .poly of CORPUS_DIR
         under 200 kB (triangles, smallest angle, and whether the Steiner cap or the two-stage take-back
         ended the run: refine/refine.cpp, refine_in_stages).
Both print Markdown tables; every run has a 120 s limit ("timeout" in the table).
"""
import argparse, math, os, re, shutil, subprocess, sys, tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, '..', 'refine'))
import corner_lopping  # noqa: E402

LOPPING_CORPUS = ['guitar.poly', 'issue-142-double-hanging-edge.poly', 'la.poly', 'clusters.poly', 'lettre_A_2.poly',
                  'fish.poly', 'fish-and-rectangle.poly', 'lake.poly', 'mesh07.poly', 'pie.poly']


def find(corpus, name):
    for root, _, files in os.walk(corpus):
        if name in files:
            return os.path.join(root, name)
    return None


def run(deltri, path, switches):
    """(status, stderr) of deltri on path in its own folder; the outputs are path's .1 files."""
    try:
        r = subprocess.run([deltri] + switches + [os.path.basename(path)], cwd=os.path.dirname(path),
                           capture_output=True, text=True, timeout=120)
        return r.returncode, r.stderr
    except subprocess.TimeoutExpired:
        return None, ''


def lopping_table(deltri, corpus, work):
    paths = corner_lopping.generated(work)
    for name in LOPPING_CORPUS:
        found = find(corpus, name)
        if found and found not in paths:
            paths.append(shutil.copy(found, os.path.join(work, name)))
    print('| input | q | Terminator: triangles, angles < q, shortest edge | corner-lopping | same mesh |')
    print('|---|---|---|---|---|')
    for path in paths:
        for q in (20, 30):
            row = []
            meshes = []
            for extra in ([], ['--corner-lopping']):
                status, _ = run(deltri, path, [f'-pq{q}Q'] + extra)
                if status != 0:
                    row.append('timeout' if status is None else f'exit {status}')
                    meshes.append(None)
                    continue
                m = corner_lopping.measure(path, path[:-5] + '.1', q)
                row.append(f'{m["triangles"]:,}, {m["under_q"]}, {m["shortest"]:.3g}')
                meshes.append(open(path[:-5] + '.1.ele', 'rb').read() + open(path[:-5] + '.1.node', 'rb').read())
            same = 'yes' if meshes[0] is not None and meshes[0] == meshes[1] else 'no'
            print(f'| {os.path.basename(path)} | {q} | {row[0]} | {row[1]} | {same} |')


def mesh_figures(path):
    base = path[:-5] + '.1'
    rows = [l.split() for l in open(base + '.node') if l.strip() and not l.startswith('#')]
    pts = {int(r[0]): (float(r[1]), float(r[2])) for r in rows[1:1 + int(rows[0][0])]}
    rows = [l.split() for l in open(base + '.ele') if l.strip() and not l.startswith('#')]
    worst = 180.0
    for r in rows[1:1 + int(rows[0][0])]:
        a, b, c = (pts[int(v)] for v in r[1:4])
        for p, q, s in ((a, b, c), (b, c, a), (c, a, b)):
            u, v = (q[0] - p[0], q[1] - p[1]), (s[0] - p[0], s[1] - p[1])
            worst = min(worst, math.degrees(math.atan2(abs(u[0] * v[1] - u[1] * v[0]), u[0] * v[0] + u[1] * v[1])))
    return int(rows[0][0]), worst


def planar(path):
    """A 2-D .poly: its header's dimension is 2 (a 3-D one is read as facets, not meshed in the plane)."""
    for line in open(path, errors='replace'):
        words = line.split('#')[0].split()
        if words:
            return len(words) > 1 and words[1] == '2'
    return False


def limits_table(deltri, corpus, work):
    files = sorted(os.path.join(root, f) for root, _, fs in os.walk(corpus) for f in fs
                   if f.endswith('.poly') and os.path.getsize(os.path.join(root, f)) < 200_000
                   and planar(os.path.join(root, f)))
    cells = ['ruppert -pq30', 'ruppert -pq33', 'ruppert -pq34', 'chew -pq30', 'chew -pq33', 'chew -pq34']
    print('| input | ' + ' | '.join(cells) + ' |')
    print('|---|' + '---|' * len(cells))
    for k, src in enumerate(files):
        path = shutil.copy(src, os.path.join(work, f'{k}_{os.path.basename(src)}'))
        row = []
        for cell in cells:
            algorithm, q = cell.split()
            status, err = run(deltri, path, [q, '--algorithm=' + algorithm])
            if status != 0:
                row.append('timeout' if status is None else f'exit {status}')
                continue
            n, worst = mesh_figures(path)
            note = ' cap' if "termination guard's cap" in err else ''
            note = ' taken back' if 'cannot reach this angle bound' in err else note
            row.append(f'{n:,}, {worst:.2f}°{note}' if n else 'no triangles')
        if not all(c.startswith('exit') or c == 'no triangles' for c in row):
            print(f'| {os.path.relpath(src, corpus)} | ' + ' | '.join(row) + ' |', flush=True)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('deltri')
    ap.add_argument('corpus')
    ap.add_argument('--table', choices=['lopping', 'limits'], default='lopping')
    a = ap.parse_args()
    with tempfile.TemporaryDirectory() as work:
        (lopping_table if a.table == 'lopping' else limits_table)(os.path.abspath(a.deltri), a.corpus, work)
    return 0


if __name__ == '__main__':
    sys.exit(main())
