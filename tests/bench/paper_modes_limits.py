#!/usr/bin/env python3
"""Time and memory of the paper's algorithms on every input (issues 16 and 22): no switch value may
make deltri grow until it is killed. Not a test (it needs the shared corpus); used for the table in
docs/reliability.md.

    paper_modes_limits.py DELTRI DIR... [--modes a,b] [--jobs 2] [--timeout 60] [--log runs.jsonl]

Every .poly under each DIR (recursively), in every mode, once, as
`timeout -s KILL T /usr/bin/time -f '%e %M' deltri SWITCHES -V file`. The paper modes run deltri's
exact check (-C) themselves and exit 6 when it fails, so status 0 means a valid mesh; the plain -pq
modes get -C added. Per run: seconds, peak resident KB, triangles, Steiner points, guard refusals
(sure-fire refusals among them), whether the Steiner cap or the guard stopped refinement. Prints one
JSON line per run, then the worst runs by time and by memory.
"""
import argparse, json, os, re, shutil, subprocess, sys, tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from paper_modes_sweep import run_jobs  # noqa: E402

MODES = {
    'ruppert -pq20.7': ['--algorithm=ruppert', '-pq20.7'],
    'ruppert -pq20.7 -D': ['--algorithm=ruppert', '-pq20.7', '-D'],
    'chew -pq26.5': ['--algorithm=chew', '-pq26.5'],
    'ruppert ib1 -pq20.7': ['--algorithm=ruppert', '--interior-bound=1', '-pq20.7'],
    'chew ib2 -pq26.5': ['--algorithm=chew', '--interior-bound=2', '-pq26.5'],
    'range-restricted -pq30': ['--range-restricted', '-pq30'],
    'ruppert -pq20': ['--algorithm=ruppert', '-pq20'],
    '-pq30': ['-pq30', '-C'],
}


def number(pattern, text, default=None):
    m = re.search(pattern, text)
    return int(m.group(1)) if m else default


def one(args, mode, path):
    work = tempfile.mkdtemp()
    try:
        shutil.copy(path, work)
        if os.path.exists(path[:-5] + '.node'):
            shutil.copy(path[:-5] + '.node', work)
        name = os.path.basename(path)
        cmd = ['timeout', '-s', 'KILL', str(args.timeout), '/usr/bin/time', '-f', 'TIME %e %M', args.deltri] + \
            MODES[mode] + ['-V', name]
        r = subprocess.run(cmd, cwd=work, capture_output=True, text=True)
        out = r.stdout + r.stderr
        rec = {'mode': mode, 'file': path, 'status': r.returncode}
        t = re.search(r'TIME ([\d.]+) (\d+)', r.stderr)
        if r.returncode == 137 or not t:
            return dict(rec, outcome='timeout', seconds=args.timeout)
        rec.update(seconds=float(t.group(1)), peak_kb=int(t.group(2)),
                   triangles=number(r'Mesh triangles: (\d+)', out),
                   steiner=sum(int(x) for x in re.findall(r'Steiner points: (\d+) interior, (\d+) on segments', out)[0])
                   if re.search(r'Steiner points: \d+ interior', out) else 0,
                   guard_refusals=number(r'guard refusals: (\d+)', out, 0),
                   sure_fire=number(r'sure-fire refusals[^:]*: (\d+)', out, 0),
                   cap="the termination guard's cap" in out,
                   check='Mesh is consistent' in out)
        rec['outcome'] = 'ok' if r.returncode == 0 and rec['check'] else 'error'
        if rec['outcome'] == 'error':
            rec['message'] = r.stderr.strip().splitlines()[-2:]
        return rec
    finally:
        shutil.rmtree(work, ignore_errors=True)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('deltri'); ap.add_argument('dirs', nargs='+')
    ap.add_argument('--modes', default=','.join(MODES)); ap.add_argument('--jobs', type=int, default=2)
    ap.add_argument('--timeout', type=int, default=60); ap.add_argument('--log', default='')
    ap.add_argument('--worst', type=int, default=12)
    args = ap.parse_args()
    args.deltri = os.path.abspath(args.deltri)
    files = sorted({os.path.join(d, f) for top in args.dirs for d, _, fs in os.walk(top) for f in fs if f.endswith('.poly')})
    jobs = [(m, f) for f in files for m in args.modes.split(',')]
    results = run_jobs(args, jobs, one)
    bad = [r for r in results if r['outcome'] != 'ok']
    print(f'{len(results)} runs, {len(bad)} timed out or failed')
    for key in ('seconds', 'peak_kb'):
        print(f'| worst by {key} | mode | s | peak MB | triangles | Steiner | guard (sure-fire) | cap |')
        print('|---|---|---|---|---|---|---|---|')
        for r in sorted(results, key=lambda r: -(r.get(key) or 0))[:args.worst]:
            print(f"| {os.path.basename(r['file'])} | {r['mode']} | {r.get('seconds')} | {(r.get('peak_kb') or 0) // 1024} "
                  f"| {r.get('triangles')} | {r.get('steiner')} | {r.get('guard_refusals')} ({r.get('sure_fire')}) "
                  f"| {r.get('cap')} {r['outcome']} |")


if __name__ == '__main__':
    main()
