#!/usr/bin/python3
"""Random sweep (issue 47): small random PSLGs at random scales (the limits of double precision
included) with random switch sets (long options included), through the command line and the
library (the Python module on libdeltri). Every run is judged:
  * exit 0: deltri_mesh_verify passes the mesh (as a refined mesh of its input when refining) and,
    when an angle bound was asked, either every triangle meets it (verify --min-angle) or stderr
    holds the warning that counts the triangles that miss the bounds; the library, given the same
    input and switches, returns the same triangle count;
  * exit non-zero: stderr is one line, and no output file is left behind; the library raises.
usage: random_sweep.py DELTRI VERIFY RUNS [SEED]     (prints one line per failure, then a summary;
       exit 1 if any run failed). Not part of CI at full size: see docs/reliability.md.
       SWEEP_ONLY=K1,K2,... runs only those runs of the same sequence (the others' inputs are drawn
       and skipped), to reproduce a failure without the whole sweep.
"""
import math
import os
import shutil
import random
import subprocess
import sys
import tempfile

DELTRI, VERIFY, RUNS = sys.argv[1], sys.argv[2], int(sys.argv[3])
rng = random.Random(int(sys.argv[4]) if len(sys.argv) > 4 else 1)
import numpy as np
try:
    import deltri as lib  # the library path (PYTHONPATH=src/api/python, DELTRI_LIBRARY=libdeltri.so)
except ImportError:
    lib = None
WORK = tempfile.mkdtemp()
SCALES = [1.0, 1.0, 1e-3, 1e6, 2.0 ** 300, 1e-300, 1e70, 1e-60, 5e-320]


def pslg():
    """Points on a small grid (so that collinear points, repeated points and crossings are common),
    jittered by a few ulps now and then, times a scale; segments between random points; a hole."""
    n = rng.randint(3, 14)
    s = rng.choice(SCALES)
    pts = []
    for _ in range(n):
        x, y = rng.randint(0, 8) / 8.0, rng.randint(0, 8) / 8.0
        if rng.random() < 0.2:
            x = float(np.nextafter(x, 2.0)) if rng.random() < 0.5 else x + 1e-15
        pts.append((x * s, y * s))
    segs = [(rng.randrange(n), rng.randrange(n)) for _ in range(rng.randint(0, n + 2))]
    segs = [(a, b) for a, b in segs if a != b]
    # A boundary square around the points, so that most inputs enclose a domain.
    base = len(pts)
    pts += [(-0.25 * s, -0.25 * s), (1.25 * s, -0.25 * s), (1.25 * s, 1.25 * s), (-0.25 * s, 1.25 * s)]
    segs += [(base, base + 1), (base + 1, base + 2), (base + 2, base + 3), (base + 3, base)]
    holes = [(rng.randint(0, 8) / 8.0 * s + s / 16, rng.randint(0, 8) / 8.0 * s + s / 16)] if rng.random() < 0.3 else []
    return pts, segs, holes, s


def switches(s):
    letters = 'p'
    angle = None
    if rng.random() < 0.7:
        angle = rng.choice([20, 25, 28.6, 30, 33, 34])
        letters += 'q%g' % angle
    if rng.random() < 0.25:
        letters += 'a%.6f' % rng.choice([0.01, 0.002]) if s == 1.0 else ''
    letters += rng.choice(['', '', 'D', 'Y', 'c', 'j', 'S200', 'X', 'o2'])
    longs = rng.choice([[], [], ['--threads=2'], ['--algorithm=ruppert'], ['--algorithm=chew'],
                        ['--range-restricted'], ['--corner-lopping'], ['--interior-bound=1']])
    return letters, longs, angle


def write_poly(path, pts, segs, holes):
    with open(path, 'w') as f:
        f.write('%d 2 0 0\n' % len(pts))
        for i, (x, y) in enumerate(pts):
            f.write('%d %r %r\n' % (i + 1, x, y))
        f.write('%d 0\n' % len(segs))
        for i, (a, b) in enumerate(segs):
            f.write('%d %d %d\n' % (i + 1, a + 1, b + 1))
        f.write('%d\n' % len(holes))
        for i, (x, y) in enumerate(holes):
            f.write('%d %r %r\n' % (i + 1, x, y))


def rescaled(name, out, pts, segs, holes):
    """deltri_mesh_verify computes in doubles: at 1e-300 or 1e90 its products underflow or
    overflow. The input and the mesh are multiplied by the power of two 2^k that brings the input
    into [1, 2) and verified there, when that is exact for every coordinate of the input and the
    mesh; otherwise (a subnormal coordinate scaled down loses bits, and then turned a valid mesh
    into one with flat triangles) the files are verified as they are. Returns the input and mesh
    names to verify."""
    k = -math.frexp(max(max(abs(x), abs(y)) for x, y in pts))[1] + 1
    if k == 0:
        return name, out

    def exact(c):
        return math.ldexp(math.ldexp(c, k), -k) == c
    rows = [l.split() for l in open(out + '.node').read().split('\n')[1:]]
    mesh = [float(c) for t in rows if len(t) >= 3 and not t[0].startswith('#') for c in t[1:3]]
    if not all(exact(c) for c in mesh + [c for p in list(pts) + list(holes) for c in p]):
        return name, out

    def scale(src, dst, first_data_line, columns):
        lines = open(src).read().split('\n')
        n = int(lines[0].split()[0]) if lines[0].split() else 0
        for i in range(first_data_line, first_data_line + n):
            t = lines[i].split()
            if len(t) >= 3 and not t[0].startswith('#'):
                t[1], t[2] = repr(math.ldexp(float(t[1]), k)), repr(math.ldexp(float(t[2]), k))
                lines[i] = ' '.join(t)
        open(dst, 'w').write('\n'.join(lines))
    def up(p):
        return (math.ldexp(p[0], k), math.ldexp(p[1], k))
    write_poly(name[:-5] + '.s.poly', [up(p) for p in pts], segs, [up(h) for h in holes])
    scale(out + '.node', name[:-5] + '.s.1.node', 1, 2)
    shutil.copy(out + '.ele', name[:-5] + '.s.1.ele')
    if os.path.exists(out + '.poly'):  # the verifier reads the output's subsegments from it
        scale(out + '.poly', name[:-5] + '.s.1.poly', 1, 2)
    return name[:-5] + '.s.poly', name[:-5] + '.s.1'


def triangles_of(path):
    with open(path) as f:
        return int(f.readline().split()[0])


ONLY = {int(k) for k in os.environ.get('SWEEP_ONLY', '').split(',') if k}


def one(k):
    pts, segs, holes, s = pslg()
    letters, longs, angle = switches(s)
    if ONLY and k not in ONLY:
        return None
    why = judge(k, pts, segs, holes, s, letters, longs, angle)
    return why and '%s (deltri -%s %s)' % (why, letters, ' '.join(longs))


def judge(k, pts, segs, holes, s, letters, longs, angle):
    name = os.path.join(WORK, 'r%d.poly' % k)
    write_poly(name, pts, segs, holes)
    out = name[:-5] + '.1'
    try:
        r = subprocess.run([DELTRI, '-' + letters] + longs + [name], capture_output=True, text=True, timeout=60)
    except subprocess.TimeoutExpired:
        return 'timeout'
    # --corner-lopping puts vertices on segments at rounded points (its shields), as refinement does.
    refining = 'q' in letters or 'a' in letters or 'D' in letters or '--corner-lopping' in longs
    if r.returncode != 0:
        if len(r.stderr.strip().splitlines()) != 1:
            return 'exit %d with %d lines on stderr' % (r.returncode, len(r.stderr.strip().splitlines()))
        if any(os.path.exists(out + e) for e in ('.node', '.ele', '.poly')):
            return 'exit %d with outputs left' % r.returncode
        cli = None
    else:
        vin, vout = rescaled(name, out, pts, segs, holes)
        args = [VERIFY, '--input', vin, '--mesh', vout] + (['--refined'] if refining else [])
        if 'c' in letters:
            args.append('--convex-hull')
        if 'o2' in letters or 'j' in letters:
            args = None  # the verifier reads 3-node triangles and the input's own numbering
        if args and subprocess.run(args, capture_output=True).returncode != 0:
            return 'exit 0, deltri_mesh_verify fails'
        if args and angle is not None and 'D' not in letters and \
                subprocess.run(args + ['--min-angle', str(angle)], capture_output=True).returncode != 0 and \
                'the requested bounds' not in r.stderr:
            return 'exit 0, triangles under %g degrees without a counted warning' % angle
        cli = triangles_of(out + '.ele')
    if lib is not None:
        d = {'vertices': np.array(pts), 'segments': np.array(segs, dtype=np.int32).reshape(-1, 2)}
        if holes:
            d['holes'] = np.array(holes)
        try:
            got = len(lib.triangulate(d, ' '.join([letters.replace('j', '')] + longs)).get('triangles', []))
        except lib.DeltriError:
            got = None
        if 'j' not in letters and (got is None) != (cli is None) or (got is not None and cli is not None and got != cli):
            return 'library: %s triangles, command line: %s' % (got, cli)
    for f in os.listdir(WORK):
        if f.startswith('r%d.' % k):
            os.unlink(os.path.join(WORK, f))
    return None


failures = {}
for k in range(RUNS):
    why = one(k)
    if why:
        failures.setdefault(why, 0)
        failures[why] += 1
        print('run %d: %s (r%d.poly kept in %s)' % (k, why, k, WORK))
print('%d runs, %d failed%s' % (RUNS, sum(failures.values()),
                               ''.join('; %d: %s' % (n, w) for w, n in failures.items())))
sys.exit(1 if failures else 0)
