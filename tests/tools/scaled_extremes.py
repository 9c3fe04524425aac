#!/usr/bin/python3
"""Randomized test of issue 17: corpus inputs moved into the extremes of the double range.

    scaled_extremes.py DELTRI DATA_DIR [SEED]

Each small input of the corpus (data/*.poly and data/*.node up to 60 kB) is scaled by a power of
two and translated so that its coordinates lie in one of these ranges, chosen at random per
input and trial:
  tiny      the largest coordinate near 2^-1060: most coordinates subnormal, rounded to
            multiples of 2^-1074 (so many vertices become duplicates or collinear);
  huge      the largest coordinate near 2^1000, translated by up to the input's own size:
            squared distances overflow;
  mixed     x scaled into the tiny range and y into the huge one (an anisotropic scaling);
  offset    the input scaled to about 2^-1070 of its size and placed at a huge offset
            (coordinates differ in their last bits only).
deltri triangulates each (-pc or -p for .poly, plain or -i for .node), and tests/tools/exact_delaunay_check.py
checks the output with exact rationals (nothing shared with deltri's predicates): triangles
strictly counter-clockwise, a consistently oriented manifold, every non-segment edge locally
Delaunay, and for a .node every input vertex used, the boundary on the convex hull and the
triangles' areas adding up to the hull's. The only input error accepted is fewer than three
distinct vertices after rounding, and in the tiny range segments that properly cross (checked here
exactly; their crossing points would be subnormal numbers off the segments); any other failure (a
refusal of the range included) fails. The seed is printed;
pass it as SEED to replay a run.
"""
import math
import os
import random
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
CHECKER = os.path.join(HERE, 'exact_delaunay_check.py')


def tokens(line):
    return line.split('#', 1)[0].split()


def any_proper_crossing(path):
    """Whether two segments of the .poly at path cross at a point interior to both (exact rationals)."""
    from fractions import Fraction
    rows = [tokens(l) for l in open(path)]
    rows = [r for r in rows if r]
    n = int(rows[0][0])
    pts = {int(r[0]): (Fraction(float(r[1])), Fraction(float(r[2]))) for r in rows[1:n + 1]}
    m = int(rows[n + 1][0])
    segs = [(pts[int(r[1])], pts[int(r[2])]) for r in rows[n + 2:n + 2 + m]]

    def orient(a, b, c):
        d = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
        return (d > 0) - (d < 0)
    for i, (a, b) in enumerate(segs):
        for c, d in segs[i + 1:]:
            if orient(a, b, c) * orient(a, b, d) < 0 and orient(c, d, a) * orient(c, d, b) < 0:
                return True
    return False


def transform_file(src, dst, fx, fy):
    """Copies src with each vertex (x, y) replaced by (fx(x), fy(y)); holes and regions too."""
    lines = open(src).read().splitlines()
    out = []
    data = [i for i, l in enumerate(lines) if tokens(l)]
    is_poly = src.endswith('.poly')
    k = 0

    def take():
        nonlocal k
        i = data[k]
        k += 1
        return i, tokens(lines[i])

    def fmt(v):
        return repr(float(v))

    i, head = take()
    n = int(head[0])
    for _ in range(n):
        j, t = take()
        t[1], t[2] = fmt(fx(float(t[1]))), fmt(fy(float(t[2])))
        lines[j] = ' '.join(t)
    if is_poly:
        _, seg = take()
        for _ in range(int(seg[0])):
            take()
        if k < len(data):
            _, hol = take()
            for _ in range(int(hol[0])):
                j, t = take()
                t[1], t[2] = fmt(fx(float(t[1]))), fmt(fy(float(t[2])))
                lines[j] = ' '.join(t)
        if k < len(data):
            _, reg = take()
            for _ in range(int(reg[0])):
                j, t = take()
                t[1], t[2] = fmt(fx(float(t[1]))), fmt(fy(float(t[2])))
                lines[j] = ' '.join(t)
    open(dst, 'w').write('\n'.join(lines) + '\n')
    return n > 0


def extent(src):
    lines = [tokens(l) for l in open(src) if tokens(l)]
    n = int(lines[0][0])
    xs = [abs(float(r[1])) for r in lines[1:1 + n]]
    ys = [abs(float(r[2])) for r in lines[1:1 + n]]
    return max(xs + [1e-300]), max(ys + [1e-300])


def mapping(mode, mx, my, rng):
    """Two functions of one coordinate each, for the mode."""
    def scale_to(m, target_exp):
        return target_exp - math.frexp(m)[1]
    if mode == 'tiny':
        ex, ey = scale_to(mx, -1060 - rng.randint(0, 8)), scale_to(my, -1060 - rng.randint(0, 8))
        return (lambda x: math.ldexp(x, ex)), (lambda y: math.ldexp(y, ey))
    if mode == 'huge':
        e = scale_to(max(mx, my), 1000 + rng.randint(0, 20))
        tx, ty = math.ldexp(rng.uniform(-1, 1) * max(mx, my), e), math.ldexp(rng.uniform(-1, 1) * max(mx, my), e)
        return (lambda x: math.ldexp(x, e) + tx), (lambda y: math.ldexp(y, e) + ty)
    if mode == 'mixed':
        ex, ey = scale_to(mx, -1055 - rng.randint(0, 10)), scale_to(my, 990 + rng.randint(0, 30))
        return (lambda x: math.ldexp(x, ex)), (lambda y: math.ldexp(y, ey))
    # offset: the shape at 2^-1070 of its size... relative to a huge translation
    e = scale_to(max(mx, my), 960 + rng.randint(0, 40))
    off_x, off_y = math.ldexp(1.0 + rng.random(), 1010), math.ldexp(-1.0 - rng.random(), 1010)
    return (lambda x: off_x + math.ldexp(x, e)), (lambda y: off_y + math.ldexp(y, e))


def main(argv):
    deltri, data_dir = argv[1], argv[2]
    seed = int(argv[3]) if len(argv) > 3 else random.SystemRandom().randrange(1 << 30)
    print('seed %d' % seed)
    rng = random.Random(seed)
    inputs = sorted(os.path.join(data_dir, f) for f in os.listdir(data_dir)
                    if f.endswith(('.poly', '.node')) and os.path.getsize(os.path.join(data_dir, f)) <= 60000)
    failures = 0
    runs = 0
    with tempfile.TemporaryDirectory() as work:
        for src in inputs:
            mx, my = extent(src)
            for mode in rng.sample(['tiny', 'huge', 'mixed', 'offset'], 2):
                fx, fy = mapping(mode, mx, my, rng)
                name = os.path.basename(src)
                dst = os.path.join(work, name)
                if not transform_file(src, dst, fx, fy):
                    continue
                base = dst.rsplit('.', 1)[0]
                switches = [rng.choice(['-pcQ', '-pQ', '-pcQ'])] if dst.endswith('.poly') else [rng.choice(['-Q', '-Q', '-iQ'])]
                proc = subprocess.run([deltri] + switches + [dst], capture_output=True, text=True, timeout=300)
                runs += 1
                label = '%s %s %s' % (mode, name, ' '.join(switches))
                # The one input error accepted: rounding into the subnormals merged the vertices.
                if proc.returncode == 1 and proc.stderr.startswith(dst) and 'at least 3 distinct vertices' in proc.stderr:
                    print('%s: input error accepted: %s' % (label, proc.stderr.splitlines()[0]))
                    continue
                # The other (issue 47): segments that properly cross where every vertex coordinate is
                # below 2^-970 (the tiny range), whose crossing points would round off the segments.
                if proc.returncode == 1 and mode == 'tiny' and 'crossing' in proc.stderr and \
                        len(proc.stderr.strip().splitlines()) == 1 and any_proper_crossing(dst):
                    print('%s: input error accepted: %s' % (label, proc.stderr.strip()[:120]))
                    continue
                if proc.returncode != 0:
                    print('FAIL %s: exit %d: %s' % (label, proc.returncode, proc.stderr.strip()[:300]))
                    failures += 1
                    continue
                check = [CHECKER, base + '.1'] + (['--convex-hull', dst] if dst.endswith('.node') else [])
                result = subprocess.run(['/usr/bin/python3'] + check, capture_output=True, text=True, timeout=600)
                status = 'ok' if result.returncode == 0 else 'FAIL'
                print('%s %s: %s' % (status, label, result.stdout.strip().splitlines()[-1] if result.stdout.strip() else ''))
                if result.returncode != 0:
                    print(result.stdout)
                    failures += 1
    print('%d runs, %d failures (seed %d)' % (runs, failures, seed))
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
