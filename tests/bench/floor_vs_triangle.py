#!/usr/bin/env python3
"""The quality floor against Triangle 1.6 (issue 42): on every corpus .poly, at -pq30 and -pq33, with
and without an area bound of the bounding box's area / 25000, both programs are run and both meshes
checked by an independent checker at the angle bound (its small-input-angle excuse applied). A file
fails when deltri leaves a triangle under the bound that the checker does not explain while
Triangle leaves none, or when deltri leaves any unexplained one without a warning (run without -V).
Not a test: it needs Triangle and the checker, passed in.

    floor_vs_triangle.py DELTRI TRIANGLE CHECKER CORPUS_DIR [--jobs 2] [--timeout 120] [--max-kb 200]

CHECKER is a program taking `--input IN --mesh BASE --min-angle Q [--max-area A] --json` and printing
a JSON object with quality.below_bound_unexplained and quality.min_angle_deg (meshcheck.py's
interface). Prints one line per run pair and a summary table.
"""
import argparse, concurrent.futures, json, math, os, shutil, subprocess, sys, tempfile


def fixed(x):
    """x in fixed notation with 7 significant digits (Triangle's -a takes no exponent)."""
    digits = max(0, 6 - math.floor(math.log10(x)))
    return f'{x:.{digits}f}'


def bbox_area(path):
    rows = [l.split('#')[0].split() for l in open(path)]
    rows = [r for r in rows if r]
    n = int(rows[0][0])
    if n == 0:
        return None
    xs = [float(r[1]) for r in rows[1:1 + n]]
    ys = [float(r[2]) for r in rows[1:1 + n]]
    return (max(xs) - min(xs)) * (max(ys) - min(ys))


def check(checker, inp, base, q, area, timeout):
    cmd = ['python3', checker] if checker.endswith('.py') else [checker]
    cmd += ['--input', inp, '--mesh', base, '--min-angle', str(q), '--json']
    if area:
        cmd += ['--max-area', area]
    try:
        r = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout * 3)
        d = json.loads(r.stdout)
        return d['quality'].get('below_bound_unexplained', 0), d['quality'].get('min_angle_deg')
    except (subprocess.TimeoutExpired, ValueError, KeyError):
        return None, None


def one(job):
    program, name, src, q, area, a = job
    work = tempfile.mkdtemp()
    try:
        inp = shutil.copy(src, os.path.join(work, os.path.basename(src)))
        switches = f'-pq{q}' + (f'a{area}' if area else '')
        cmd = [program, switches, os.path.basename(inp)]
        try:
            r = subprocess.run(cmd, cwd=work, capture_output=True, text=True, timeout=a.timeout)
        except subprocess.TimeoutExpired:
            return job, 'timeout', None, None, ''
        base = inp[:-5] + '.1'
        if r.returncode != 0 or not os.path.exists(base + '.ele'):
            return job, f'exit {r.returncode}', None, None, r.stderr
        unexplained, worst = check(a.checker, inp, base, q, area, a.timeout)
        return job, 'ok', unexplained, worst, r.stderr
    finally:
        shutil.rmtree(work, ignore_errors=True)


def main():
    ap = argparse.ArgumentParser()
    for arg in ('deltri', 'triangle', 'checker', 'corpus'):
        ap.add_argument(arg)
    ap.add_argument('--jobs', type=int, default=2)
    ap.add_argument('--timeout', type=float, default=120)
    ap.add_argument('--max-kb', type=int, default=200)
    a = ap.parse_args()
    files = sorted(os.path.join(r, f) for r, _, fs in os.walk(a.corpus) for f in fs
                   if f.endswith('.poly') and os.path.getsize(os.path.join(r, f)) < a.max_kb * 1024)
    jobs = []
    for src in files:
        try:
            box = bbox_area(src)
        except (ValueError, IndexError):
            continue
        for q in (30, 33):
            for area in (None, fixed(box / 25000) if box else None):
                for program in (a.deltri, a.triangle):
                    jobs.append((program, os.path.relpath(src, a.corpus), src, q, area, a))
            if not box:
                break
    results = {}
    with concurrent.futures.ThreadPoolExecutor(a.jobs) as pool:
        for job, status, unexplained, worst, err in pool.map(one, jobs):
            program, name, _, q, area, _ = job
            results[(name, q, area, program == a.deltri)] = (status, unexplained, worst, err)
    failures = 0
    keys = sorted({k[:3] for k in results}, key=lambda k: (k[0], k[1], k[2] or ''))
    print('| file | switches | deltri: unexplained, smallest angle | Triangle 1.6 | verdict |')
    print('|---|---|---|---|---|')
    for name, q, area in keys:
        d = results.get((name, q, area, True))
        t = results.get((name, q, area, False))
        cell = lambda r: r[0] if r[0] != 'ok' else f'{r[1]}, {r[2]:.3f}' if r[1] is not None and r[2] is not None else 'unchecked'
        verdict = 'ok'
        if d[0] == 'ok' and d[1]:
            if t[0] == 'ok' and t[1] == 0:
                verdict = 'FAIL: Triangle has none'
            if 'miss' not in d[3]:
                verdict = 'FAIL: not warned'
        failures += verdict != 'ok'
        print(f'| {name} | -pq{q}{"a" + area if area else ""} | {cell(d)} | {cell(t)} | {verdict} |', flush=True)
    print(f'\n{len(keys)} run pairs, {failures} failing')
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())
