#!/usr/bin/env python3
"""make bench: generate workloads, run deltri on them, print the figures as Markdown tables.

Nothing here asserts anything: benchmarks are measurements, not tests. Each case runs REPEAT
times and the median wall time is shown; peak memory is the child's maximum resident set size.
Usage: bench.py BUILD_DIR [--quick] [--only SUBSTRING] [--large]

The threads table runs the workloads with --threads=N for every N of BENCH_THREADS (a list, default
"1 2": this machine's two cores), the values of N interleaved round by round, and reports each
one's wall time, peak and speed-up over N = 1 (the files are the same for every N). A machine with
more cores runs e.g. BENCH_THREADS="1 2 4 8 16 32 64" make bench.

--large (make bench-large, not part of CI or make test): only the 100M+ triangle workload, the unit
square refined to about 134 million triangles (BENCH_LARGE_AREA sets the area bound), once per N
of BENCH_THREADS, with its time, stage timings and peak memory. It needs about 8 GiB of memory and
8 GB of disk for the text outputs, which are removed afterwards.

When Triangle 1.6 is installed (a `triangle` on PATH, e.g. Debian's non-free triangle-bin, or
TRIANGLE=/path/to/triangle), every case also runs it with the same switches, interleaved with
deltri's runs so that both meet the same host, and the tables add its time, peak and the ratio of
the two throughputs (triangles per second, end to end with outputs written). The ratio is the
median over the rounds of each round's ratio (a deltri run and the Triangle run right after it),
which a host whose speed drifts from minute to minute disturbs less than a ratio of medians.
Triangle is only run, never built or read: it is a measuring stick. BENCH_REPEAT=n sets the
number of rounds (default 3, 1 with --quick).
"""
import os
import shutil
import statistics
import subprocess
import sys
import time

build = sys.argv[1] if len(sys.argv) > 1 else "build"
quick = "--quick" in sys.argv
large = "--large" in sys.argv
only = sys.argv[sys.argv.index("--only") + 1] if "--only" in sys.argv else ""
deltri = os.path.abspath(os.path.join(build, "deltri"))
gen = os.path.abspath(os.path.join(build, "tests", "deltri_bench_gen"))
work = os.path.abspath(os.path.join(build, "bench"))
os.makedirs(work, exist_ok=True)
REPEAT = int(os.environ.get("BENCH_REPEAT", "1" if quick else "3"))
triangle = os.environ.get("TRIANGLE") or shutil.which("triangle")
THREADS = [int(n) for n in os.environ.get("BENCH_THREADS", "1 2").replace(",", " ").split()]


def workload(kind, size, ext):
    path = os.path.join(work, f"{kind}{size}.{ext}")
    if not os.path.exists(path):
        args = [gen, kind, str(size), path] if kind not in ("square",) else [gen, kind, path]
        subprocess.run(args, check=True)
    return path


def remove_outputs(path):
    stem = os.path.splitext(path)[0]
    for ext in (".node", ".ele", ".poly", ".edge", ".neigh"):
        if os.path.exists(stem + ".1" + ext):
            os.remove(stem + ".1" + ext)


def run(switches, path, verbose, threads=None):
    """One run: (wall seconds, peak RSS bytes, stage seconds dict, triangle count). Outputs of an
    earlier run are removed first, so every run writes new files (replacing large files costs the
    file system extra time that has nothing to do with deltri)."""
    remove_outputs(path)
    flags = "-" + switches.lstrip("-") + ("V" if verbose else "")
    start = time.perf_counter()
    thread_args = [f"--threads={threads}"] if threads else []
    proc = subprocess.Popen([deltri, flags, *thread_args, os.path.basename(path)], cwd=os.path.dirname(path),
                            stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
    out = proc.stdout.read()
    _, status, usage = os.wait4(proc.pid, 0)
    wall = time.perf_counter() - start
    if status != 0:
        raise SystemExit(f"deltri {switches} {path} failed with status {status}")
    stages, triangles = {}, 0
    in_stages = False
    for line in out.splitlines():
        if line.startswith("Stage timings"):
            in_stages = True
            continue
        if in_stages and line.startswith("  ") and line.rstrip().endswith(" s"):
            name, secs = line[:24].strip(), float(line.split()[-2])
            stages[name] = secs
            continue
        in_stages = False
        if " triangles;" in line or " triangle;" in line:
            triangles = int(line.split(" -> ")[1].split(", ")[1].split()[0])
    return wall, usage.ru_maxrss * 1024, stages, triangles


def run_triangle(switches, path):
    """One run of Triangle 1.6 with the same switches: (wall seconds, peak RSS bytes, triangles)."""
    remove_outputs(path)
    start = time.perf_counter()
    proc = subprocess.Popen([triangle, "-" + switches.lstrip("-") + "Q", os.path.basename(path)],
                            cwd=os.path.dirname(path), stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    _, status, usage = os.wait4(proc.pid, 0)
    wall = time.perf_counter() - start
    if status != 0:
        raise SystemExit(f"triangle {switches} {path} failed with status {status}")
    with open(os.path.splitext(path)[0] + ".1.ele") as f:
        triangles = int(f.readline().split()[0])
    return wall, usage.ru_maxrss * 1024, triangles


def measure(switches, path):
    """Wall time and peak memory from plain runs; stage timings from -V runs (-V also computes
    the quality statistics, which would inflate the end-to-end time). With Triangle available,
    its runs alternate with deltri's plain runs; its figures come back as `reference`, else None."""
    plain, theirs = [], []
    for _ in range(REPEAT):
        plain.append(run(switches, path, False))
        if triangle:
            theirs.append(run_triangle(switches, path))
    verbose = [run(switches, path, True) for _ in range(REPEAT)]
    wall = statistics.median(r[0] for r in plain)
    rss = max(r[1] for r in plain)
    stage = {k: statistics.median(r[2].get(k, 0.0) for r in verbose) for k in verbose[0][2]}
    reference = None
    if theirs:
        rounds = statistics.median(t[0] / d[0] for d, t in zip(plain, theirs) if d[0] > 0)
        reference = (statistics.median(r[0] for r in theirs), max(r[1] for r in theirs), theirs[0][2], rounds)
    return wall, rss, stage, verbose[0][3], reference


def reference_columns(reference, wall, tris):
    """The extra cells for Triangle: its triangles, time and peak, and deltri's throughput over its."""
    if reference is None:
        return ""
    t_wall, t_rss, t_tris, time_ratio = reference
    speedup = tris / t_tris * time_ratio if t_tris else 0.0
    return f" {t_tris:,} | {t_wall:.3f} | {mib(t_rss)} | {speedup:.2f}x |"


def print_table_header(header, rule):
    """The table's header and rule lines, with Triangle's columns when it runs alongside."""
    if triangle:
        header += " Triangle triangles | Triangle s | Triangle peak | throughput ratio |"
        rule += "---|---|---|---|"
    print(header)
    print(rule)


def mib(b):
    return f"{b / 2**20:.0f} MiB"


def point_sets():
    sizes = [100_000, 1_000_000] if quick else [100_000, 1_000_000, 4_000_000]
    print("## Delaunay triangulation of point sets (`deltri -V pts.node`, writes .node and .ele)\n")
    print_table_header("| points | kind | triangles | triangulation s | end to end s | peak | bytes/point | bytes/triangle |",
                       "|---|---|---|---|---|---|---|---|")
    for size in sizes:
        for kind in ("uniform", "gaussian", "grid", "clustered"):
            if only and only not in kind:
                continue
            path = workload(kind, size, "node")
            wall, rss, stage, tris, reference = measure("", path)
            print(f"| {size:,} | {kind} | {tris:,} | {stage.get('Delaunay', 0):.3f} | {wall:.3f} | {mib(rss)} "
                  f"| {rss / size:.0f} | {rss / max(tris, 1):.0f} |{reference_columns(reference, wall, tris)}", flush=True)
    print()


def algorithms():
    """-F (Fortune's sweepline) against divide and conquer and -i on a million points, in memory
    (tests/bench/sweepline_vs_dc.cpp); it also checks that -F and -i give divide and conquer's
    triangles, ties included, and fails the bench if not."""
    if only and only not in "sweepline":
        return
    print("## Delaunay algorithms: divide and conquer, sweepline (-F), incremental (-i), 1M points, in memory\n")
    n = "100000" if quick else "1000000"
    subprocess.run([os.path.join(build, "tests", "deltri_sweepline_vs_dc"), n], check=True)
    print()


def pslgs():
    print("## PSLGs: unit square with k x k circular holes of 64 segments (`deltri -pV`)\n")
    print_table_header("| holes | vertices and segments | switches | triangles | end to end s | peak | bytes/triangle |",
                       "|---|---|---|---|---|---|---|")
    for k, switches in ((45, "-p"), (100, "-p"), (45, "-pq30")):
        if only and only not in "holes":
            continue
        path = workload("holes", k, "poly")
        wall, rss, stage, tris, reference = measure(switches, path)
        print(f"| {k}x{k} | {4 + 64 * k * k:,} | `{switches}` | {tris:,} | {wall:.3f} | {mib(rss)} | {rss / max(tris, 1):.0f} |"
              f"{reference_columns(reference, wall, tris)}", flush=True)
    print()


def refinement():
    print("## Quality refinement on the unit square (`deltri -pq30a<A>V square.poly`)\n")
    print_table_header("| switches | triangles | refinement s | end to end s | triangles/s | peak | bytes/triangle |",
                       "|---|---|---|---|---|---|---|")
    areas = ["0.0000016"] if quick else ["0.0000016", "0.00000032"]
    for area in areas:
        if only and only not in "square":
            continue
        path = workload("square", 0, "poly")
        switches = f"-pq30a{area}"
        wall, rss, stage, tris, reference = measure(switches, path)
        print(f"| `{switches}` | {tris:,} | {stage.get('refinement', 0):.3f} | {wall:.3f} | {tris / wall:,.0f} "
              f"| {mib(rss)} | {rss / max(tris, 1):.0f} |{reference_columns(reference, wall, tris)}", flush=True)
    print()


def soak():
    """The reliability soak (issue 5): 1,000,004 segments (125 x 125 holes) refined with -pq30a to
    about ten million triangles, once (it is heavy); it must finish and pass -C."""
    if quick or (only and only not in "soak"):
        return
    print("## Soak: 125 x 125 holes (1,000,004 segments), `deltri -pq30a1.2e-7C`, one run\n")
    print("| segments | triangles | end to end s | peak | bytes/triangle |")
    print("|---|---|---|---|---|")
    path = workload("holes", 125, "poly")
    wall, rss, _, tris = run("-pq30a0.00000012C", path, False)
    if tris == 0:  # plain runs print only the summary line; count the .ele instead
        with open(os.path.splitext(path)[0] + ".1.ele") as f:
            tris = int(f.readline().split()[0])
    print(f"| 1,000,004 | {tris:,} | {wall:.1f} | {mib(rss)} | {rss / max(tris, 1):.0f} |", flush=True)
    remove_outputs(path)
    print()


def thread_workloads():
    """(label, switches, path) of every workload of the threads table."""
    sizes = [1_000_000] if quick else [1_000_000, 4_000_000]
    cases = [(f"{n // 1_000_000}M uniform points", "", workload("uniform", n, "node")) for n in sizes]
    for k in (45,) if quick else (45, 50):
        cases.append((f"{k}x{k} holes `-pq30`", "-pq30", workload("holes", k, "poly")))
    for area in ["0.0000016"] if quick else ["0.0000016", "0.00000032"]:
        cases.append((f"unit square `-pq30a{area}`", f"-pq30a{area}", workload("square", 0, "poly")))
    return [c for c in cases if not only or only in c[0]]


def threads():
    """Every workload with --threads=N for each N of BENCH_THREADS, the Ns interleaved round by
    round (so a host whose speed drifts meets all of them alike): median wall time, peak, and the
    speed-up over the first N (1 by default)."""
    cases = thread_workloads()
    if not cases:
        return
    print(f"## Threads: `--threads=N` for N = {', '.join(map(str, THREADS))} (speed-up over N = {THREADS[0]})\n")
    print("| workload | triangles | " + " | ".join(f"N = {n} s (peak)" for n in THREADS) + " | "
          + " | ".join(f"speed-up N = {n}" for n in THREADS[1:]) + " |")
    print("|---|---|" + "---|" * (2 * len(THREADS) - 1))
    for label, switches, path in cases:
        runs = {n: [] for n in THREADS}
        for _ in range(REPEAT):
            for n in THREADS:
                runs[n].append(run(switches.lstrip("-"), path, False, n))
        wall = {n: statistics.median(r[0] for r in runs[n]) for n in THREADS}
        peak = {n: max(r[1] for r in runs[n]) for n in THREADS}
        tris = runs[THREADS[0]][0][3] or count_triangles(path)
        cells = [f"{wall[n]:.3f} ({mib(peak[n])})" for n in THREADS]
        cells += [f"{wall[THREADS[0]] / wall[n]:.2f}x" for n in THREADS[1:]]
        print(f"| {label} | {tris:,} | " + " | ".join(cells) + " |", flush=True)
        remove_outputs(path)
    print()


def count_triangles(path):
    """The triangle count from the .ele file that a run left (plain runs print no counts)."""
    with open(os.path.splitext(path)[0] + ".1.ele") as f:
        return int(f.readline().split()[0])


def bench_large():
    """make bench-large: the unit square refined to 100M+ triangles, once per N of BENCH_THREADS."""
    area = os.environ.get("BENCH_LARGE_AREA", "0.0000000125")
    path = workload("square", 0, "poly")
    print(f"## Large: unit square `-pq30a{area}`, one run per N\n")
    print("| N | triangles | wall s (with -V's statistics) | stages total s | refinement s | write s | peak | bytes/triangle |")
    print("|---|---|---|---|---|---|---|---|")
    for n in THREADS:
        wall, rss, stage, tris = run(f"pq30a{area}", path, True, n)
        tris = tris or count_triangles(path)
        print(f"| {n} | {tris:,} | {wall:.1f} | {stage.get('total', 0):.1f} | {stage.get('refinement', 0):.1f} | {stage.get('write', 0):.1f} "
              f"| {rss / 2**30:.2f} GiB | {rss / max(tris, 1):.1f} |", flush=True)
        remove_outputs(path)
    print()


if __name__ == "__main__":
    if large:
        print(f"deltri large benchmark on {os.cpu_count()} cores\n")
        bench_large()
        sys.exit(0)
    print(f"deltri benchmarks on {os.cpu_count()} cores; median of {REPEAT} run(s)"
          + (f"; Triangle 1.6 from {triangle} alongside" if triangle else "") + "\n")
    point_sets()
    algorithms()
    pslgs()
    refinement()
    threads()
    soak()
