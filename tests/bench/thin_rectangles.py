#!/usr/bin/env python3
"""Issue 45's thin domains: the rectangles 1 x 1e-3 .. 1 x 1e-6 at -pq30Q, deltri against Triangle
1.6 (and, with --baseline, another deltri build), and the unit square refined to about the same
triangle count for the triangles-per-second comparison. A measurement, not a test: nothing is
asserted; the figures are printed as a Markdown table for docs/benchmarks.md ("Thin domains").

    thin_rectangles.py DELTRI TRIANGLE [--baseline DELTRI_B] [--rounds N] [--exponents 3,4,5,6]

Every round runs each program once on each rectangle, one after the other (interleaved, so that
all meet the same host); the table gives each program's median wall seconds, CPU seconds (user +
system, from wait4) and peak resident memory. The rectangle's side 10^-k is written in fixed
notation (Triangle's readers take no exponent in -a; here it keeps the .poly plain)."""
import argparse
import os
import shutil
import statistics
import subprocess
import tempfile
import threading
import time

ap = argparse.ArgumentParser()
ap.add_argument("deltri")
ap.add_argument("triangle")
ap.add_argument("--baseline", help="a second deltri (for example main's) run alongside")
ap.add_argument("--rounds", type=int, default=3)
ap.add_argument("--exponents", default="3,4,5,6")
ap.add_argument("--square-area", default="0.0000005", help="-a of the unit square run (2,097,152 triangles)")
args = ap.parse_args()
programs = [("Triangle 1.6", os.path.abspath(args.triangle)), ("deltri", os.path.abspath(args.deltri))]
if args.baseline:
    programs.append(("deltri (baseline)", os.path.abspath(args.baseline)))


def run(argv, cwd, timeout=1800):
    """(wall s, CPU s, peak MiB, triangles written) of one run."""
    start = time.perf_counter()
    proc = subprocess.Popen(argv, cwd=cwd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    guard = threading.Timer(timeout, proc.kill)  # a guard against a hang, not a measure
    guard.start()
    _, status, usage = os.wait4(proc.pid, 0)
    wall = time.perf_counter() - start
    guard.cancel()
    if os.waitstatus_to_exitcode(status) != 0:
        raise SystemExit(f"{argv} failed")
    stem = os.path.join(cwd, os.path.splitext(argv[-1])[0])
    with open(stem + ".1.ele") as f:
        triangles = int(f.readline().split()[0])
    for ext in (".node", ".ele", ".poly"):
        os.remove(stem + ".1" + ext)
    return wall, usage.ru_utime + usage.ru_stime, usage.ru_maxrss / 1024, triangles


def rectangle(work, name, height):
    with open(os.path.join(work, name), "w") as f:
        f.write(f"4 2 0 0\n1 0 0\n2 1 0\n3 1 {height}\n4 0 {height}\n4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n0\n")


work = tempfile.mkdtemp()
cases = []
for k in (int(e) for e in args.exponents.split(",")):
    name = f"thin{k}.poly"
    rectangle(work, name, format(10.0 ** -k, f".{k}f"))
    cases.append((f"1 x 1e-{k}", ["-pq30Q", name]))
rectangle(work, "square.poly", "1")
cases.append((f"unit square -a{args.square_area}", [f"-pq30Qa{args.square_area}", "square.poly"]))

got = {(case, name): [] for case, _ in cases for name, _ in programs}
triangles = {}
for _ in range(args.rounds):
    for case, switches in cases:
        for name, binary in programs:
            wall, cpu, peak, tris = run([binary] + switches, work)
            got[(case, name)].append((wall, cpu, peak))
            triangles[(case, name)] = tris
shutil.rmtree(work)

print(f"Median of {args.rounds} interleaved rounds; load average before: {os.getloadavg()[0]:.1f}\n")
print("| domain | program | triangles | wall s | CPU s | peak MiB | triangles per CPU s | wall / Triangle's | peak / Triangle's |")
print("|---|---|---|---|---|---|---|---|---|")
for case, _ in cases:
    ref = [statistics.median(x[i] for x in got[(case, programs[0][0])]) for i in range(3)]
    for name, _ in programs:
        wall, cpu, peak = (statistics.median(x[i] for x in got[(case, name)]) for i in range(3))
        tris = triangles[(case, name)]
        print(f"| {case} | {name} | {tris:,} | {wall:.2f} | {cpu:.2f} | {peak:.0f} | {tris / cpu:,.0f} "
              f"| {wall / ref[0]:.2f} | {peak / ref[2]:.2f} |")
