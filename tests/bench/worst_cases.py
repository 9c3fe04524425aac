#!/usr/bin/env python3
"""Issue 45's table of the worst cases, deltri against Triangle 1.6, every comparison interleaved
run by run in one sitting (docs/benchmarks.md, "The worst cases against Triangle 1.6").

A measurement, not a test: nothing is asserted; the figures are printed as one Markdown table.

    worst_cases.py DELTRI TRIANGLE BENCH_GEN --corpus DIR [--runs 3] [--only PARTS] [--timeout 60]

BENCH_GEN is build/tests/deltri_bench_gen (the uniform points of the -F/-i rows). PARTS
(comma-separated, default all):
  corpus  every .poly under DIR at -pQ, -pq30Q and -pq33Q, each program --runs times (alternating),
          the median wall time; the deltri/Triangle ratio per file over the files Triangle needs
          20 ms or more for, and over every file both mesh: median and worst (with its file). A
          file where either program fails (Triangle 1.6 crashes on some) or passes --timeout is
          left out and named.
  batch   200 and 1,000 copies of data/guitar.poly in one fresh folder, meshed with
          `xargs -P $(nproc) -n 1 PROGRAM -pq30Q` (the names listed, not globbed): wall seconds,
          the median of --runs rounds; and whether anything reached standard error.
  thin    the rectangles 1 x 1e-3 .. 1 x 1e-6 at -pq30Q: wall seconds and peak memory.
  rchain  a -r chain: the unit square at -pq30a0.001, then three refinements of the previous
          output with -rpq30 and the area bound halved each time (.node, .ele, .poly read back):
          the chain's total wall seconds.
  points  one million uniform points (BENCH_GEN uniform) triangulated by default (divide and
          conquer), with -F (sweepline) and with -i (incremental), -Q, writing .node/.ele.
deltri runs with its default threads, as a user's command line does; the load average is printed
with each part. Triangle's peak memory and deltri's come from wait4's ru_maxrss.
"""
import argparse
import os
import shutil
import statistics
import subprocess
import tempfile
import threading
import time

here = os.path.dirname(os.path.abspath(__file__))
guitar = os.path.join(here, "..", "..", "data", "guitar.poly")
ap = argparse.ArgumentParser()
ap.add_argument("deltri")
ap.add_argument("triangle")
ap.add_argument("bench_gen")
ap.add_argument("--corpus", required=True)
ap.add_argument("--runs", type=int, default=3)
ap.add_argument("--only", default="corpus,batch,thin,rchain,points")
ap.add_argument("--timeout", type=float, default=60)
args = ap.parse_args()
parts = set(args.only.split(","))
programs = [("Triangle 1.6", os.path.abspath(args.triangle)), ("deltri", os.path.abspath(args.deltri))]
rows = []  # (case, Triangle, deltri, ratio, note)


def run(argv, cwd, timeout):
    """(wall s, peak KiB, stderr bytes, exit status); status None when killed at the timeout."""
    with tempfile.TemporaryFile() as err:
        start = time.perf_counter()
        proc = subprocess.Popen(argv, cwd=cwd, stdout=subprocess.DEVNULL, stderr=err)
        killed = []
        guard = threading.Timer(timeout, lambda: (killed.append(1), proc.kill()))
        guard.start()
        _, status, usage = os.wait4(proc.pid, 0)
        wall = time.perf_counter() - start
        guard.cancel()
        err.seek(0)
        return wall, usage.ru_maxrss, len(err.read()), None if killed else os.waitstatus_to_exitcode(status)


def interleaved(make_argv, setup, timeout):
    """Runs each program --runs times, alternating (the order reversed every other run), each in a
    fresh folder set up by setup(dir);
    returns {name: (median wall, max peak KiB, stderr bytes)} or the failure's description."""
    walls = {name: [] for name, _ in programs}
    peaks = {name: 0 for name, _ in programs}
    errs = {name: 0 for name, _ in programs}
    for r in range(args.runs):
        # The order alternates from run to run: a run can pay for what the one before it left
        # (deleted inodes that file creation steps past, a cold cache).
        for name, prog in programs if r % 2 == 0 else programs[::-1]:
            work = tempfile.mkdtemp()
            try:
                argv = setup(work) or []
                wall, peak, err, status = run(make_argv(prog, argv), work, timeout)
            finally:
                shutil.rmtree(work)
            if status != 0:
                return f"{name} {'timed out' if status is None else f'exit {status}'}"
            walls[name].append(wall)
            peaks[name] = max(peaks[name], peak)
            errs[name] += err
    return {name: (statistics.median(walls[name]), peaks[name], errs[name]) for name, _ in programs}


def add(case, got, note=""):
    t, d = got["Triangle 1.6"][0], got["deltri"][0]
    rows.append((case, f"{t:.3f}", f"{d:.3f}", f"{d / t:.2f}", note))


def load():
    return f"load {os.getloadavg()[0]:.1f}"


def part_corpus():
    files = sorted(os.path.join(d, f) for d, _, fs in os.walk(args.corpus) for f in fs if f.endswith(".poly"))
    for switch in ("-pQ", "-pq30Q", "-pq33Q"):
        note = load()
        ratios, left_out = [], []
        for path in files:
            def setup(work, path=path):
                shutil.copy(path, work)
                node = path[:-len(".poly")] + ".node"
                if os.path.exists(node):
                    shutil.copy(node, work)
            got = interleaved(lambda prog, _, s=switch, n=os.path.basename(path): [prog, s, n], setup, args.timeout)
            if isinstance(got, str):
                left_out.append(f"{os.path.basename(path)} ({got})")
                continue
            t, d = got["Triangle 1.6"][0], got["deltri"][0]
            ratios.append((d / t, os.path.basename(path), t))
        for label, chosen in (("Triangle >= 20 ms", [r for r in ratios if r[2] >= 0.020]), ("every file", ratios)):
            if not chosen:
                continue
            chosen.sort()
            worst = chosen[-1]
            med = statistics.median(r for r, _, _ in chosen)
            rows.append((f"corpus `{switch}`, {label} ({len(chosen)} files)", "-", "-",
                         f"median {med:.2f}, worst {worst[0]:.2f}",
                         f"worst: {worst[1]} (Triangle {worst[2] * 1000:.0f} ms); {note}"))
        if left_out:
            rows.append((f"corpus `{switch}`: left out", "-", "-", "-", ", ".join(left_out)))


def part_batch():
    jobs = str(os.cpu_count() or 1)
    for count in (200, 1000):
        note = load()
        names = [f"f{i}.poly" for i in range(count)]

        def setup(work):
            for n in names:
                shutil.copy(guitar, os.path.join(work, n))
            with open(os.path.join(work, "list"), "w") as f:
                f.write("\n".join(names))
        got = interleaved(lambda prog, _: ["sh", "-c", f"xargs -P {jobs} -n 1 {prog} -pq30Q < list"], setup, 600)
        if isinstance(got, str):
            rows.append((f"batch of {count} guitar.poly", "-", "-", "-", got))
            continue
        add(f"batch of {count} guitar.poly, `xargs -P {jobs}` (wall of the batch)", got,
            f"stderr bytes: Triangle {got['Triangle 1.6'][2]}, deltri {got['deltri'][2]}; {note}")


def rectangle(work, h):
    with open(os.path.join(work, "thin.poly"), "w") as f:
        f.write(f"4 2 0 0\n1 0 0\n2 1 0\n3 1 {h}\n4 0 {h}\n4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n0\n")


def part_thin():
    for h in ("0.001", "0.0001", "0.00001", "0.000001"):
        note = load()
        got = interleaved(lambda prog, _: [prog, "-pq30Q", "thin.poly"], lambda w, h=h: rectangle(w, h), 1200)
        if isinstance(got, str):
            rows.append((f"rectangle 1 x {float(h):g} `-pq30Q`", "-", "-", "-", got))
            continue
        t_peak, d_peak = got["Triangle 1.6"][1] / 1024, got["deltri"][1] / 1024
        add(f"rectangle 1 x {float(h):g} `-pq30Q`", got, f"peak {t_peak:.0f} / {d_peak:.0f} MiB ({d_peak / t_peak:.2f}); {note}")


def part_rchain():
    note = load()
    script = ("{p} -pq30a0.001Q sq.poly && {p} -rpq30a0.0005Q sq.1 && {p} -rpq30a0.00025Q sq.2 && "
              "{p} -rpq30a0.000125Q sq.3")
    got = interleaved(lambda prog, _: ["sh", "-c", script.format(p=prog)], lambda w: rectangle(w, "1") or
                      os.rename(os.path.join(w, "thin.poly"), os.path.join(w, "sq.poly")), 600)
    if isinstance(got, str):
        rows.append(("-r chain", "-", "-", "-", got))
        return
    add("-r chain: unit square `-pq30a0.001`, then `-rpq30a` 0.0005, 0.00025, 0.000125", got, note)


def part_points():
    with tempfile.TemporaryDirectory() as gen:
        pts = os.path.join(gen, "pts.node")
        subprocess.run([args.bench_gen, "uniform", "1000000", pts], check=True, stdout=subprocess.DEVNULL)
        for label, switch in (("divide and conquer", "-Q"), ("sweepline `-F`", "-FQ"), ("incremental `-i`", "-iQ")):
            note = load()
            got = interleaved(lambda prog, _, s=switch: [prog, s, "pts.node"], lambda w: shutil.copy(pts, w), 1200)
            if isinstance(got, str):
                rows.append((f"1M uniform points, {label}", "-", "-", "-", got))
                continue
            add(f"1M uniform points, {label}", got, f"peak {got['Triangle 1.6'][1] / 1024:.0f} / "
                f"{got['deltri'][1] / 1024:.0f} MiB; {note}")


for part, fn in [("corpus", part_corpus), ("batch", part_batch), ("thin", part_thin), ("rchain", part_rchain),
                 ("points", part_points)]:
    if part in parts:
        fn()
print(f"wall seconds, median of {args.runs} interleaved runs; ratio deltri / Triangle 1.6\n")
print("| case | Triangle 1.6 s | deltri s | ratio | notes |")
print("|---|---|---|---|---|")
for r in rows:
    print("| " + " | ".join(r) + " |")
