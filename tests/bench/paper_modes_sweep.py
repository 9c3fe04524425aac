#!/usr/bin/env python3
"""The corpus sweep of the paper's other algorithms (issue 22): every mode at the bounds it allows,
each run twice, checked by an independent checker. Not a test (it needs the shared corpus and
meshcheck.py); used for the table in docs/refinement.md.

    paper_modes_sweep.py DELTRI CORPUS_DIR REFERENCE.md MESHCHECK [--modes a,b] [--jobs 2]
                         [--timeout 120] [--log runs.jsonl]

The corpus is the files of REFERENCE.md that exist under CORPUS_DIR (as corpus_counts.py builds it),
smallest first.
Per run: `deltri SWITCHES -Q file` twice with a timeout; then meshcheck.py with --min-angle the
mode's q (and --conforming-delaunay with -D). A run is
  pass           status 0, meshcheck OK;
  reported       status 0, meshcheck fails only on angles, and deltri warned that triangles miss
                 the requested bounds or accounts for them with -V (its reasons, kept in the log:
                 next to small input angles, next to repaired crossings, other); with -D also
                 edges not Delaunay when deltri warned of exactly that many subsegments not Delaunay;
  silent         status 0, meshcheck fails and deltri did not warn (or meshcheck fails on more
                 than angles): a bug;
  unchecked      meshcheck did not finish (its own time limit) or could not read the files;
  error          a non-zero status (an input deltri refuses);
  timeout        the first run did not end within the timeout (no second run);
  nondeterministic  the two runs wrote different bytes (counted besides the above).
meshcheck accepts a boundary edge off its recovered chain when both ends lie on one segment within its
tolerance, but only for the first 200; its other "does not lie on an input segment" failures are
checked here (both ends within 16 ulps of one input segment, exactly) and, if all pass, counted in the
log (boundary_within_16_ulps) instead of failing the run. Prints one line per run and the table per mode.
"""
import argparse, concurrent.futures, json, os, re, shutil, subprocess, tempfile

MODES = {
    'ruppert -pq20': (['-pq20', '--algorithm=ruppert'], 20.0),
    'ruppert -pDq20.7': (['-pDq20.7', '--algorithm=ruppert'], 20.7),
    'chew -pq20': (['-pq20', '--algorithm=chew'], 20.0),
    'chew -pq26.5': (['-pq26.5', '--algorithm=chew'], 26.5),
    'ruppert ib1 -pq20.7': (['-pq20.7', '--algorithm=ruppert', '--interior-bound=1'], 20.7),
    'ruppert ib2 -pq20.7': (['-pq20.7', '--algorithm=ruppert', '--interior-bound=2'], 20.7),
    'chew ib1 -pq26.5': (['-pq26.5', '--algorithm=chew', '--interior-bound=1'], 26.5),
    'chew ib2 -pq26.5': (['-pq26.5', '--algorithm=chew', '--interior-bound=2'], 26.5),
    'range-restricted -pq20': (['-pq20', '--range-restricted'], 20.0),
    'range-restricted -pq30': (['-pq30', '--range-restricted'], 30.0),
    'range-restricted -pq33': (['-pq33', '--range-restricted'], 33.0),
    'corner-lopping -pq20': (['-pq20', '--corner-lopping'], 20.0),
    'corner-lopping -pq30': (['-pq30', '--corner-lopping'], 30.0),
}


def corpus(corpus_dir, reference):
    files = []
    for line in open(reference):
        m = re.match(r'\| (\S+\.poly) \|', line)
        if m and os.path.exists(os.path.join(corpus_dir, m.group(1))):
            files.append(m.group(1))
    return sorted(files, key=lambda f: (os.path.getsize(os.path.join(corpus_dir, f)), f))  # small ones first


def output_base(name):
    """The output's name: x.poly gives x.1, x.1.poly (an earlier output) gives x.2."""
    m = re.match(r'(.*)\.(\d+)\.poly$', name)
    return f'{m.group(1)}.{int(m.group(2)) + 1}' if m else name[:-5] + '.1'


def deltri_once(deltri, switches, work, name, timeout):
    base = os.path.join(work, output_base(name))
    for ext in ('node', 'ele', 'poly'):
        if os.path.exists(f'{base}.{ext}'):
            os.remove(f'{base}.{ext}')
    r = subprocess.run([deltri] + switches + ['-Q', name], cwd=work, capture_output=True, text=True, timeout=timeout)
    data = b''.join(open(f'{base}.{ext}', 'rb').read() for ext in ('node', 'ele', 'poly') if os.path.exists(f'{base}.{ext}'))
    return r.returncode, r.stderr, data


def boundary_edges_on_segments(cmd, path, timeout):
    """meshcheck again with every example listed: the number of its failing boundary edges, if each has
    both ends within 16 ulps (meshcheck's --seg-tol, of the segment's largest coordinate) of one input
    segment, between its ends; None if one does not (or meshcheck did not finish)."""
    try:
        m = subprocess.run(cmd + ['--max-examples', '1000000'], capture_output=True, text=True, timeout=timeout)
        failures = json.loads(m.stdout).get('failures', [])
    except (subprocess.TimeoutExpired, ValueError):
        return None
    rows = [l.split('#', 1)[0].split() for l in open(path)]
    rows = [r for r in rows if r]
    n = int(rows[0][0])
    pts = {int(r[0]): (float(r[1]), float(r[2])) for r in rows[1:1 + n]}
    m = int(rows[1 + n][0])
    segs = [(pts[int(r[1])], pts[int(r[2])]) for r in rows[2 + n:2 + n + m] if int(r[1]) in pts and int(r[2]) in pts]
    segs = [(a, b) for a, b in segs if a != b]
    edge = re.compile(r'\[\(([-\d.e+]+), ([-\d.e+]+)\) - \(([-\d.e+]+), ([-\d.e+]+)\)\] does not lie on')
    count = 0
    for f in failures:
        if not f.startswith('[boundary]'):
            continue
        e = edge.search(f)
        if not e:
            return None
        u, w = (float(e.group(1)), float(e.group(2))), (float(e.group(3)), float(e.group(4)))
        if not any(on_segment(u, a, b) and on_segment(w, a, b) for a, b in segs):
            return None
        count += 1
    return count


def on_segment(p, a, b):
    """p within 16 ulps of the largest coordinate of segment ab, and between its ends (exact)."""
    from fractions import Fraction as F
    (px, py), (ax, ay), (bx, by) = [(F(x), F(y)) for x, y in (p, a, b)]
    tol = 16 * F(2.0 ** -52) * max(abs(ax), abs(ay), abs(bx), abs(by))
    dx, dy = bx - ax, by - ay
    cross, length2 = dx * (py - ay) - dy * (px - ax), dx * dx + dy * dy
    along = dx * (px - ax) + dy * (py - ay)
    before = along < 0 and along * along > tol * tol * length2  # more than tol before a
    beyond = along > length2 and (along - length2) ** 2 > tol * tol * length2  # more than tol beyond b
    return cross * cross <= tol * tol * length2 and not before and not beyond


def one(args, mode, f):
    switches, q = MODES[mode]
    work = tempfile.mkdtemp()
    try:
        path = os.path.join(args.corpus, f)
        shutil.copy(path, work)
        if os.path.exists(path[:-5] + '.node'):
            shutil.copy(path[:-5] + '.node', work)
        name = os.path.basename(f)
        rec = {'mode': mode, 'file': f}
        try:
            status, err, data = deltri_once(args.deltri, switches, work, name, args.timeout)
        except subprocess.TimeoutExpired:
            return dict(rec, outcome='timeout')
        rec['status'] = status
        if status != 0:
            return dict(rec, outcome='error', message=err.strip().splitlines()[-1:] )
        try:
            again = deltri_once(args.deltri, switches, work, name, args.timeout)
            rec['deterministic'] = again[0] == status and again[2] == data
        except subprocess.TimeoutExpired:
            rec['deterministic'] = False
        # "1 triangle misses" as well as "N triangles miss"
        warned = re.search(r'(\d+) triangles? miss(?:es)? the requested bounds[^\n]*', err)
        rec['warning'] = warned.group(0) if warned else ''
        cmd = ['/usr/bin/python3', args.meshcheck, '--input', os.path.join(work, name),
               '--mesh', os.path.join(work, output_base(name)), '--min-angle', str(q), '--json']
        if '-pDq20.7' in switches:
            cmd.append('--conforming-delaunay')
        try:
            m = subprocess.run(cmd, capture_output=True, text=True, timeout=args.check_timeout)
            check = json.loads(m.stdout)
        except (subprocess.TimeoutExpired, ValueError):
            return dict(rec, outcome='unchecked')
        counts = dict(check.get('failure_counts', {}))
        if 'boundary' in counts:
            # meshcheck accepts a boundary edge off its recovered chain when both ends lie on one segment
            # within its tolerance, but only for its first 200 such edges; the rest are checked here.
            near = boundary_edges_on_segments(cmd, path, args.check_timeout)
            if near is not None:
                rec['boundary_within_16_ulps'] = near
                del counts['boundary']
        rec['failures'] = counts
        rec['unexplained'] = check.get('quality', {}).get('below_bound_unexplained')
        if not counts:
            rec['outcome'] = 'pass'
            return rec
        # -D: subsegments left not Delaunay are reported when deltri's count is meshcheck's.
        conformity = re.search(r'(\d+) subsegments? (?:is|are) not Delaunay', err)
        if 'delaunay' in counts and conformity and int(conformity.group(1)) == counts['delaunay']:
            rec['conformity_warning'] = conformity.group(0)
            del counts['delaunay']
        if not counts:
            rec['outcome'] = 'reported'
            return rec
        if set(counts) <= {'angle'}:
            # deltri's own account of the misses (-V): next to small input angles, repaired crossings, other
            try:
                v = subprocess.run([args.deltri] + switches + ['-V', name], cwd=work, capture_output=True, text=True,
                                   timeout=args.timeout)
                cause = re.search(r'by cause: ([^\n]*)', v.stdout + v.stderr)
                rec['cause'] = cause.group(1) if cause else ''
            except subprocess.TimeoutExpired:
                rec['cause'] = ''
        rec['outcome'] = 'reported' if set(counts) <= {'angle'} and (warned or rec['cause']) else 'silent'
        return rec
    finally:
        shutil.rmtree(work, ignore_errors=True)


def run_jobs(args, jobs, run_one):
    """run_one(args, *job) for every job on args.jobs threads; prints each record as a JSON line
    (and appends it to args.log); returns the records."""
    results = []
    log = open(args.log, 'a') if args.log else None
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        for rec in concurrent.futures.as_completed([pool.submit(run_one, args, *j) for j in jobs]):
            rec = rec.result()
            results.append(rec)
            print(json.dumps(rec), flush=True)
            if log:
                log.write(json.dumps(rec) + '\n'); log.flush()
    return results


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('deltri'); ap.add_argument('corpus'); ap.add_argument('reference'); ap.add_argument('meshcheck')
    ap.add_argument('--modes', default=','.join(MODES)); ap.add_argument('--jobs', type=int, default=2)
    ap.add_argument('--timeout', type=float, default=120); ap.add_argument('--check-timeout', type=float, default=300)
    ap.add_argument('--files', default='', help='comma-separated subset of the corpus')
    ap.add_argument('--log', default='')
    args = ap.parse_args()
    args.deltri = os.path.abspath(args.deltri)
    files = corpus(args.corpus, args.reference)
    if args.files:
        files = [f for f in files if f in args.files.split(',')]
    modes = args.modes.split(',')
    jobs = [(m, f) for f in files for m in modes]  # file by file: a partial sweep covers every mode
    results = run_jobs(args, jobs, one)
    print('| mode | runs | pass | reported | silent | unchecked | error | timeout | nondeterministic |')
    print('|---|---|---|---|---|---|---|---|---|')
    for mode in modes:
        rs = [r for r in results if r['mode'] == mode]
        n = {k: sum(r['outcome'] == k for r in rs) for k in ('pass', 'reported', 'silent', 'unchecked', 'error', 'timeout')}
        nd = sum(r.get('deterministic') is False for r in rs)
        print(f"| {mode} | {len(rs)} | {n['pass']} | {n['reported']} | {n['silent']} | {n['unchecked']} | {n['error']} "
              f"| {n['timeout']} | {nd} |")


if __name__ == '__main__':
    main()
