#!/usr/bin/env python3
"""Issue 45's "must show" figures: deltri against Triangle 1.6 where the work is small.

A measurement, not a test: nothing is asserted; the figures are printed as Markdown tables for
docs/benchmarks.md ("Small files"). Every comparison interleaves the two programs run by run, so
that both meet the same host.

    small_files.py DELTRI TRIANGLE [--corpus DIR] [--rounds N] [--batch N] [--only PARTS]

PARTS (comma-separated, default all): cpu, batch, corpus-batch, corpus, thin.
  cpu     guitar.poly -pq30Q, 20 runs of each program per round, alternating; CPU time (user +
          system) of each run from wait4(), deltri with --threads=1. The mean per round.
  batch   N copies (default 200) of guitar.poly in one fresh folder, meshed with
          `xargs -P 2 -n 1 PROGRAM -pq30Q` (the names listed, not globbed); wall seconds per round,
          the batch's CPU seconds (user + system, from xargs's wait4(), which counts the runs it
          waited for; load distorts it less than the wall time), and whatever the runs wrote on
          standard error. The load average is printed first and after each round. A third column
          runs deltri --each, the names split in two lists over `xargs -P 2` (one process a core).
  corpus-batch  the same batch of N files taken from the corpus instead: every .poly under DIR
          with no .node beside it that Triangle meshes at -pq30Q in under 20 ms and both programs
          mesh with exit 0 and nothing on standard error, in name order, over and over up to N.
  corpus  every .poly under DIR at -pQ and -pq30Q (--switches), each program three times (alternating), the
          median wall time; the deltri/Triangle ratio over the files Triangle needs 20 ms or more
          for: median, worst, and the five worst files, and the same two of the CPU time; a file where a run fails (Triangle 1.6 crashes on
          some) or passes --timeout (60 s) is left out and named.
  thin    the rectangle 1 x 1e-6 at -pq30Q: wall seconds and peak resident memory, once per round.
guitar.poly is read from the repository's data/ folder.
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
ap.add_argument("--corpus", default=os.path.join(here, "..", "..", "data"))
ap.add_argument("--rounds", type=int, default=3)
ap.add_argument("--batch", type=int, default=200)
ap.add_argument("--only", default="cpu,batch,corpus-batch,corpus,thin")
ap.add_argument("--switches", default="-pQ,-pq30Q", help="the corpus part's switch sets")
ap.add_argument("--timeout", type=float, default=60, help="a corpus run's limit; a file past it is left out")
args = ap.parse_args()
parts = set(args.only.split(","))
deltri, triangle = os.path.abspath(args.deltri), os.path.abspath(args.triangle)
programs = [("Triangle 1.6", [triangle]), ("deltri", [deltri, "--threads=1"])]


def run(argv, cwd, timeout=600):
    """Runs argv in cwd; returns (wall seconds, CPU seconds, peak KiB, stderr bytes, exit status)."""
    with tempfile.TemporaryFile() as err:
        start = time.perf_counter()
        proc = subprocess.Popen(argv, cwd=cwd, stdout=subprocess.DEVNULL, stderr=err)
        guard = threading.Timer(timeout, proc.kill)  # a guard against a hang, not a measure
        guard.start()
        _, status, usage = os.wait4(proc.pid, 0)
        wall = time.perf_counter() - start
        guard.cancel()
        proc.returncode = os.waitstatus_to_exitcode(status)
        err.seek(0)
        return wall, usage.ru_utime + usage.ru_stime, usage.ru_maxrss, len(err.read()), proc.returncode


def part_cpu():
    print("### guitar.poly -pq30Q: CPU ms per run (mean of 20 runs per round, interleaved)\n")
    work = tempfile.mkdtemp()
    shutil.copy(guitar, os.path.join(work, "guitar.poly"))
    print("| round | load | " + " | ".join(name for name, _ in programs) + " | ratio |")
    print("|---|---|" + "---|" * (len(programs) + 1))
    for r in range(args.rounds):
        cpu = {name: [] for name, _ in programs}
        for _ in range(20):
            for name, argv in programs:
                cpu[name].append(run(argv + ["-pq30Q", "guitar.poly"], work)[1] * 1000)
        means = [statistics.mean(cpu[name]) for name, _ in programs]
        print(f"| {r + 1} | {os.getloadavg()[0]:.1f} | " + " | ".join(f"{m:.2f}" for m in means) +
              f" | {means[1] / means[0]:.2f} |")
    shutil.rmtree(work)
    print()


def batch_ways():
    """The batch's command lines: each program once a file, and deltri --each in two lists."""
    half = (args.batch + 1) // 2
    ways = [(name, ["-n", "1", argv[0], "-pq30Q"]) for name, argv in programs]  # default threads, as a batch runs it
    ways.append(("deltri --each", ["-n", str(half), deltri, "-pq30Q", "--each"]))
    return ways


def batch_round(sources, ways):
    """One round: for each way, the files `sources` copied as f0000-NAME.poly ... into a fresh
    folder and meshed by `xargs -P 2`; returns the walls, the batches' CPU seconds and, per way,
    the bytes on standard error (plus 1 for a failed xargs, 1,000,000 for a file left unmeshed)."""
    walls, cpus, errs = [], [], []
    for name, xargs_tail in ways:
        work = tempfile.mkdtemp()
        names = [f"f{i:04d}-{os.path.basename(src)}" for i, src in enumerate(sources)]
        for n, src in zip(names, sources):
            shutil.copy(src, os.path.join(work, n))
        with tempfile.TemporaryFile() as listing, tempfile.TemporaryFile() as err:
            listing.write("\n".join(names).encode())
            listing.seek(0)
            start = time.perf_counter()
            p = subprocess.Popen(["xargs", "-P", "2"] + xargs_tail, stdin=listing, cwd=work,
                                 stdout=subprocess.DEVNULL, stderr=err)
            # xargs's rusage covers the runs it waited for: the CPU of the whole batch.
            _, status, usage = os.wait4(p.pid, 0)
            walls.append(time.perf_counter() - start)
            cpus.append(usage.ru_utime + usage.ru_stime)
            err.seek(0)
            errs.append(len(err.read()) + (0 if os.waitstatus_to_exitcode(status) == 0 else 1))
        written = sum(1 for f in os.listdir(work) if f.endswith(".1.ele"))
        if written != len(sources):
            errs[-1] += 1000000  # a batch that did not mesh every file: shown, not compared
        shutil.rmtree(work)
    return walls, cpus, errs


def batch_table(sources, ways):
    """The batch's rounds as a Markdown table, one row a round."""
    print("| round | load | " + " | ".join(f"{name} wall | {name} CPU" for name, _ in ways) +
          " | wall ratio | CPU ratio | --each wall ratio | stderr bytes |")
    print("|---|---|" + "---|" * (2 * len(ways) + 4))
    for r in range(args.rounds):
        walls, cpus, errs = batch_round(sources, ways)
        print(f"| {r + 1} | {os.getloadavg()[0]:.1f} | " + " | ".join(f"{w:.2f} | {c:.2f}" for w, c in zip(walls, cpus)) +
              f" | {walls[1] / walls[0]:.2f} | {cpus[1] / cpus[0]:.2f} | {walls[2] / walls[0]:.2f} | " +
              ", ".join(map(str, errs)) + " |")
    print()


def part_batch():
    load = os.getloadavg()
    half = (args.batch + 1) // 2
    ways = batch_ways()
    print(f"### {args.batch} copies of guitar.poly, `xargs -P 2 -n 1 PROGRAM -pq30Q` in one folder (and deltri "
          f"`--each` with `xargs -P 2 -n {half}`): wall s and their CPU s (user + system) "
          f"(load average at the start {load[0]:.2f} {load[1]:.2f} {load[2]:.2f}; per round, the 1-minute one at its end)\n")
    batch_table([guitar] * args.batch, ways)


def small_corpus_files():
    """The corpus's small files, for the batch: every .poly with no .node beside it that Triangle
    meshes at -pq30Q in under 20 ms (its median of 3 runs) and both programs mesh with exit 0 and
    nothing on standard error (an input warning is not the batch's concern), in name order."""
    files = sorted(os.path.join(d, f) for d, _, fs in os.walk(args.corpus) for f in fs if f.endswith(".poly"))
    small = []
    for path in files:
        if os.path.exists(path[:-len(".poly")] + ".node"):
            continue
        work = tempfile.mkdtemp()
        shutil.copy(path, work)
        name = os.path.basename(path)
        t = [run([triangle, "-pq30Q", name], work, timeout=args.timeout) for _ in range(3)]
        d = run([deltri, "-pq30Q", name], work, timeout=args.timeout)
        shutil.rmtree(work)
        if all(x[4] == 0 and x[3] == 0 for x in t + [d]) and statistics.median(x[0] for x in t) < 0.020:
            small.append(path)
    return small


def part_corpus_batch():
    small = small_corpus_files()
    sources = [small[i % len(small)] for i in range(args.batch)]
    load = os.getloadavg()
    ways = batch_ways()
    print(f"### {args.batch} small corpus files, `xargs -P 2 -n 1 PROGRAM -pq30Q` in one folder (and deltri "
          f"`--each` with `xargs -P 2 -n {(args.batch + 1) // 2}`): wall s and their CPU s (user + system)\n")
    print(f"The {len(small)} files Triangle meshes in under 20 ms with nothing on standard error, taken in "
          f"name order over and over up to {args.batch}: {', '.join(os.path.basename(f) for f in small)} "
          f"(load average at the start {load[0]:.2f} {load[1]:.2f} {load[2]:.2f}; per round, the 1-minute one at its end)\n")
    batch_table(sources, ways)


def part_corpus():
    files = sorted(os.path.join(d, f) for d, _, fs in os.walk(args.corpus) for f in fs if f.endswith(".poly"))
    print(f"### Corpus ({len(files)} .poly files under {os.path.basename(os.path.abspath(args.corpus))}): "
          "deltri/Triangle wall ratio, median of 3 interleaved runs, files Triangle needs >= 20 ms for\n")
    print(f"(load average at the start {os.getloadavg()[0]:.2f}; CPU: user + system of the same runs, median of 3)\n")
    print("| switches | files | median ratio | worst ratio | worst five | CPU median ratio | CPU worst ratio | "
          "left out (a run failed or passed the time limit) |")
    print("|---|---|---|---|---|---|---|---|")
    for switch in args.switches.split(","):
        ratios, left_out, cpu_ratios = [], [], []
        for path in files:
            work = tempfile.mkdtemp()
            local = os.path.join(work, os.path.basename(path))
            shutil.copy(path, local)
            base = path[:-len(".poly")]
            if os.path.exists(base + ".node"):
                shutil.copy(base + ".node", local[:-len(".poly")] + ".node")
            walls = {name: [] for name, _ in programs}
            cpus = {name: [] for name, _ in programs}
            failed = []
            for _ in range(3):
                for name, argv in programs:
                    wall, cpu, _, _, status = run([argv[0], switch, os.path.basename(local)], work, timeout=args.timeout)
                    walls[name].append(wall)
                    cpus[name].append(cpu)
                    if status != 0 or wall >= args.timeout:
                        failed.append(f"{name} {'timed out' if wall >= args.timeout else f'exit {status}'}")
                if failed:
                    break
            shutil.rmtree(work)
            if failed:  # no ratio against a run that crashed or was cut short
                left_out.append(f"{os.path.basename(path)} ({', '.join(failed)})")
                continue
            t, d = (statistics.median(walls[name]) for name, _ in programs)
            ct, cd = (statistics.median(cpus[name]) for name, _ in programs)
            if t >= 0.020:
                ratios.append((d / t, os.path.basename(path), t))
                cpu_ratios.append(cd / ct if ct > 0 else float("nan"))
        ratios.sort()
        worst = ", ".join(f"{n} {r:.2f} ({t * 1000:.0f} ms)" for r, n, t in reversed(ratios[-5:]))
        med = statistics.median(r for r, _, _ in ratios) if ratios else float("nan")
        cmed = statistics.median(cpu_ratios) if cpu_ratios else float("nan")
        cworst = max(cpu_ratios) if cpu_ratios else float("nan")
        print(f"| `{switch}` | {len(ratios)} | {med:.2f} | {ratios[-1][0] if ratios else float('nan'):.2f} | {worst} | "
              f"{cmed:.2f} | {cworst:.2f} | {', '.join(left_out) or 'none'} |")
    print()


def part_thin():
    print("### The rectangle 1 x 1e-6 at -pq30Q (wall s, peak MiB)\n")
    work = tempfile.mkdtemp()
    with open(os.path.join(work, "thin.poly"), "w") as f:
        f.write("4 2 0 0\n1 0 0\n2 1 0\n3 1 0.000001\n4 0 0.000001\n4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n0\n")
    print("| round | " + " | ".join(f"{name} s | {name} MiB" for name, _ in programs) + " | time ratio | peak ratio |")
    print("|---|" + "---|" * (2 * len(programs) + 2))
    for r in range(args.rounds):
        got = []
        for name, argv in programs:
            wall, _, peak, _, _ = run([argv[0], "-pq30Q", "thin.poly"], work, timeout=1200)
            got.append((wall, peak / 1024))
        print(f"| {r + 1} | " + " | ".join(f"{w:.2f} | {m:.0f}" for w, m in got) +
              f" | {got[1][0] / got[0][0]:.2f} | {got[1][1] / got[0][1]:.2f} |")
    shutil.rmtree(work)
    print()


for part, fn in [("cpu", part_cpu), ("batch", part_batch), ("corpus-batch", part_corpus_batch), ("corpus", part_corpus),
                 ("thin", part_thin)]:
    if part in parts:
        fn()
