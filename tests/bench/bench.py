#!/usr/bin/env python3
"""make bench: generate workloads, run deltri on them, print the figures as Markdown tables.

Nothing here asserts anything: benchmarks are measurements, not tests. Each case runs REPEAT
times and the median wall time is shown; peak memory is the child's maximum resident set size.
Usage: bench.py BUILD_DIR [--quick] [--only SUBSTRING]

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
only = sys.argv[sys.argv.index("--only") + 1] if "--only" in sys.argv else ""
deltri = os.path.abspath(os.path.join(build, "deltri"))
gen = os.path.abspath(os.path.join(build, "tests", "deltri_bench_gen"))
work = os.path.abspath(os.path.join(build, "bench"))
os.makedirs(work, exist_ok=True)
REPEAT = int(os.environ.get("BENCH_REPEAT", "1" if quick else "3"))
triangle = os.environ.get("TRIANGLE") or shutil.which("triangle")


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


def run(switches, path, verbose):
    """One run: (wall seconds, peak RSS bytes, stage seconds dict, triangle count). Outputs of an
    earlier run are removed first, so every run writes new files (replacing large files costs the
    file system extra time that has nothing to do with deltri)."""
    remove_outputs(path)
    flags = "-" + switches.lstrip("-") + ("V" if verbose else "")
    start = time.perf_counter()
    proc = subprocess.Popen([deltri, flags, os.path.basename(path)], cwd=os.path.dirname(path),
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


if __name__ == "__main__":
    print(f"deltri benchmarks on {os.cpu_count()} cores; median of {REPEAT} run(s)"
          + (f"; Triangle 1.6 from {triangle} alongside" if triangle else "") + "\n")
    point_sets()
    algorithms()
    pslgs()
    refinement()
    soak()
