#!/usr/bin/env python3
"""Byte-identical outputs of two deltri binaries (issue 43: a restructuring of src/refine must not
change a mesh). Not a test (it needs the shared corpus); its result is recorded in
docs/refinement.md ("The policies").

    byte_identical.py OLD NEW CORPUS_DIR [--jobs 2] [--timeout 120] [--modes NAME,...]

Every .poly under CORPUS_DIR, in every mode of MODES, is meshed by both binaries in fresh
directories of their own; the run counts as identical when both exit with the same status and
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
    "pq33a0.01": ["-pq33a0.01"],
    "pq33a": ["-pq33a{area}"],
    "ruppert": ["--algorithm=ruppert", "-pq25"],
    "chew": ["--algorithm=chew", "-pq28"],
    "range": ["--range-restricted", "-pq30"],
    "lopping": ["--corner-lopping", "-pq30"],
    "Y": ["-pYq30"],
    "YY": ["-pYYq30"],
}
COMPARED = (".node", ".ele", ".poly", ".edge")


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


def run(binary, switches, poly, timeout):
    work = tempfile.mkdtemp(prefix="byteid-")
    name = os.path.basename(poly)
    shutil.copy(poly, os.path.join(work, name))
    node = poly[:-5] + ".node"
    if os.path.exists(node):
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
    ap.add_argument("corpus")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--timeout", type=float, default=120.0)
    ap.add_argument("--modes", default=",".join(MODES))
    args = ap.parse_args()
    polys = sorted(os.path.join(d, f) for d, _, fs in os.walk(args.corpus) for f in fs if f.endswith(".poly"))
    jobs = []
    for poly in polys:
        area = area_of(poly)
        for mode in args.modes.split(","):
            switches = [s.format(area=area) for s in MODES[mode]]
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
