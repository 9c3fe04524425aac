#!/usr/bin/env python3
"""Byte-identical outputs of two deltri binaries (issue 43: a restructuring of src/refine must not
change a mesh). Not a test (it needs the shared corpus); its result is recorded in
docs/refinement.md ("The policies").

    byte_identical.py OLD NEW CORPUS_DIR... [--jobs 2] [--timeout 120] [--modes NAME,...]
                      [--nodes] [--max-bytes N]

Every .poly under each CORPUS_DIR (with --nodes also every .node without a .poly beside it, meshed
with the modes' switches less -p; with --max-bytes only the files up to N bytes), in every mode of
MODES, is meshed by both binaries in fresh directories of their own; the mode "own" takes the
switches from the input's first line, "# deltri SWITCHES" (tests/regression/inputs/), and skips
the inputs without one; the run counts as identical when both exit with the same status and
write the same set of files, and every .node, .ele, .poly and .edge file is the same byte for byte.
A run that times out under both binaries is counted apart (it compares nothing). The area bound of
the -a mode is 1/10000 of the input's bounding box, written without an exponent (Triangle's -a
parser reads none). Exit status 1 when any run differs."""
import argparse
import concurrent.futures
import decimal
import filecmp
import os
import shutil
import subprocess
import sys
import tempfile

MODES = {
    "p": ["-p"],
    "pq20": ["-pq20"],
    "pq30": ["-pq30"],
    "pq33": ["-pq33"],
    "pq33a0.01": ["-pq33a0.01"],
    "pq33a": ["-pq33a{area}"],
    "ruppert": ["--algorithm=ruppert", "-pq25"],
    "chew": ["--algorithm=chew", "-pq28"],
    "range": ["--range-restricted", "-pq30"],
    "lopping": ["--corner-lopping", "-pq30"],
    "Y": ["-pYq30"],
    "YY": ["-pYYq30"],
    "pq20": ["-pq20"],
    "pq33a0.01": ["-pq33a0.01"],
    "ruppert25": ["--algorithm=ruppert", "-pq25"],
    "chew25": ["--algorithm=chew", "-pq25"],
    "interior1": ["--algorithm=ruppert", "--interior-bound=1", "-pq20"],
    "interior2": ["--algorithm=ruppert", "--interior-bound=2", "-pq20"],
    "chew_interior1": ["--algorithm=chew", "--interior-bound=1", "-pq25"],
    "chew_interior2": ["--algorithm=chew", "--interior-bound=2", "-pq25"],
    "decline": ["--decline-cluster-splits", "-pq30"],
    "pq40": ["-pq40"],
    "pq34": ["-pq34"],
    "offcentre34": ["--steiner=offcentre", "-pq34"],
    "lopping34": ["--corner-lopping", "-pq34"],
    "own": [],
}
COMPARED = (".node", ".ele", ".poly", ".edge")
DEFAULT_MODES = ("p", "pq30", "pq33a", "ruppert", "chew", "range", "lopping", "Y", "YY")


def numbers(line):
    out = []
    for word in line.split("#")[0].split():
        try:
            out.append(float(word))
        except ValueError:
            break
    return out


def node_lines(path):
    """The vertex lines of a .poly (or of the .node file beside it when the .poly lists none)."""
    lines = [n for n in (numbers(l) for l in open(path, encoding="utf-8", errors="replace")) if n]
    count = int(lines[0][0])
    if count == 0:
        node = path[:-5] + ".node"
        if not os.path.exists(node):
            return []
        lines = [n for n in (numbers(l) for l in open(node, encoding="utf-8", errors="replace")) if n]
        count = int(lines[0][0])
    return [l for l in lines[1:count + 1] if len(l) >= 3]


def area_of(path):
    points = node_lines(path)
    if not points:
        return "0.01"
    xs = [p[1] for p in points]
    ys = [p[2] for p in points]
    area = (max(xs) - min(xs)) * (max(ys) - min(ys)) / 10000.0
    if not area > 0.0:
        return "0.01"
    return format(decimal.Decimal(repr(area)), "f")


def own_switches(path):
    with open(path, encoding="utf-8", errors="replace") as f:
        first = f.readline()
    return first[len("# deltri "):].split() if first.startswith("# deltri ") else None


def switches_for(mode, path, area):
    if mode == "own":
        return own_switches(path)
    switches = [s.format(area=area) for s in MODES[mode]]
    if path.endswith(".node"):  # a point set: the same switches without -p
        switches = [s.replace("p", "", 1) if s.startswith("-p") else s for s in switches]
        switches = [s for s in switches if s != "-"]
    return switches


def run(binary, switches, poly, timeout):
    work = tempfile.mkdtemp(prefix="byteid-")
    name = os.path.basename(poly)
    shutil.copy(poly, os.path.join(work, name))
    node = poly[:-5] + ".node"
    if poly.endswith(".poly") and os.path.exists(node):
        shutil.copy(node, os.path.join(work, name[:-5] + ".node"))
    before = set(os.listdir(work))
    try:
        status = subprocess.run([binary, *switches, "-Q", name], cwd=work, stdout=subprocess.DEVNULL,
                                stderr=subprocess.DEVNULL, timeout=timeout).returncode
    except subprocess.TimeoutExpired:
        status = "timeout"
    made = sorted(set(os.listdir(work)) - before)
    return work, status, made


def compare(old, new, switches, poly, timeout):
    a = run(old, switches, poly, timeout)
    b = run(new, switches, poly, timeout)
    try:
        if a[1] == "timeout" and b[1] == "timeout":
            return "both timed out"
        if a[1] != b[1]:
            return f"status {a[1]} against {b[1]}"
        if a[2] != b[2]:
            return f"files {a[2]} against {b[2]}"
        for f in a[2]:
            if f.endswith(COMPARED) and not filecmp.cmp(os.path.join(a[0], f), os.path.join(b[0], f), shallow=False):
                return f"{f} differs"
        return "identical"
    finally:
        shutil.rmtree(a[0], ignore_errors=True)
        shutil.rmtree(b[0], ignore_errors=True)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("old")
    ap.add_argument("new")
    ap.add_argument("corpus", nargs="+")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--timeout", type=float, default=120.0)
    ap.add_argument("--modes", default=",".join(m for m in MODES if m in DEFAULT_MODES))
    ap.add_argument("--nodes", action="store_true")
    ap.add_argument("--max-bytes", type=int, default=0)
    args = ap.parse_args()
    polys = []
    for corpus in args.corpus:
        for d, _, fs in os.walk(corpus):
            for f in fs:
                lone_node = args.nodes and f.endswith(".node") and f[:-5] + ".poly" not in fs
                if f.endswith(".poly") or lone_node:
                    polys.append(os.path.join(d, f))
    polys = sorted(p for p in polys if not args.max_bytes or os.path.getsize(p) <= args.max_bytes)
    jobs = []
    for poly in polys:
        area = area_of(poly) if poly.endswith(".poly") else "0.01"
        for mode in args.modes.split(","):
            switches = switches_for(mode, poly, area)
            if switches is not None:
                jobs.append((mode, poly, switches))
    tally = {}
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        futures = {pool.submit(compare, os.path.abspath(args.old), os.path.abspath(args.new), s, p, args.timeout):
                   (m, p, s) for m, p, s in jobs}
        for future in concurrent.futures.as_completed(futures):
            mode, poly, switches = futures[future]
            verdict = future.result()
            key = "identical" if verdict == "identical" else "both timed out" if verdict == "both timed out" else "different"
            tally.setdefault(mode, {}).setdefault(key, 0)
            tally[mode][key] += 1
            if key != "identical":
                print(f"{key.upper()}: {' '.join(switches)} {poly}: {verdict}", flush=True)
    total = {}
    for mode in args.modes.split(","):
        counts = tally.get(mode, {})
        for k, v in counts.items():
            total[k] = total.get(k, 0) + v
        print(f"{mode:8} {' '.join(MODES[mode]):32} " + ", ".join(f"{v} {k}" for k, v in sorted(counts.items())))
    print(f"{len(polys)} files, {len(jobs)} runs per binary: " + ", ".join(f"{v} {k}" for k, v in sorted(total.items())))
    return 1 if total.get("different") else 0


if __name__ == "__main__":
    sys.exit(main())
