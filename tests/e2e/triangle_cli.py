#!/usr/bin/python3
"""Issue 46: Triangle's command line where scripts notice.

  triangle_cli.py DELTRI INPUTS_DIR DATA_DIR ITEM    ITEM: stock_u | poly_for_node | ignorable_letters |
                                                  dimension3 | messages

stock_u: -pqu (bare -u, Triangle's stock triunsuitable) on plate_markers.poly. Every output
  triangle must pass the stock test -- longest edge squared <= 0.05 (x^2 + y^2) + 0.02 -- at one
  corner at least, as every triangle of Triangle 1.6's own -pqu mesh does (checked with
  Triangle 1.6 run by hand: 258 triangles, 0 failing at all three corners); the test must have acted
  (more triangles than -pq alone; Triangle: 258 against 24), and the count lies within 25% of
  Triangle's 258. -pqu0.5 is deltri's edge-length bound: no edge above 0.5.
poly_for_node: -p plate.node beside plate.poly reads the .poly (its holes and segments: the
  triangles cover the plate's area less its holes, 7.5, not the convex hull's 8) and
  writes a .poly; with no plate.poly it fails naming plate.poly.
ignorable_letters: -pL runs as -D with a one-line notice; -pw, -pW, -po3, -pS2.5, -pq. run with
  exit 0 and one notice each; -pH and -p? print the help and exit 0.
dimension3: a 2-D .poly whose header says dimension 3 fails (status 1) with file:line naming the
  dimension, nothing written.
messages: --triangle-messages counts the vertices in triangles (Triangle's 144 on guitar.poly -p,
  whose .node keeps 148), and with -V prints the aspect-ratio histogram, whose counts are
  recomputed here from the .node/.ele (longest edge / shortest altitude, bins closed above).
"""
import math
import os
import shutil
import subprocess
import sys
import tempfile

DELTRI, INPUTS, DATA, ITEM = os.path.abspath(sys.argv[1]), sys.argv[2], sys.argv[3], sys.argv[4]
failures = []


def check(ok, message):
    if not ok:
        failures.append(message)
        print("FAIL:", message)


def run(work, *args):
    return subprocess.run([DELTRI, *args], cwd=work, capture_output=True, text=True, timeout=300)


def rows(path):
    out = [l.split("#")[0].split() for l in open(path)]
    return [r for r in out if r]


def mesh(base):
    node, ele = rows(base + ".node"), rows(base + ".ele")
    points = {int(r[0]): (float(r[1]), float(r[2])) for r in node[1:int(node[0][0]) + 1]}
    return points, [tuple(int(x) for x in r[1:4]) for r in ele[1:int(ele[0][0]) + 1]]


def d2(p, q):
    return (p[0] - q[0]) ** 2 + (p[1] - q[1]) ** 2


def area(a, b, c):
    return abs((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])) / 2


def stock_u(work):
    shutil.copy(os.path.join(INPUTS, "plate_markers.poly"), os.path.join(work, "plate.poly"))
    p = run(work, "-Qpq", "plate.poly")
    check(p.returncode == 0, f"-pq: {p.stderr}")
    plain = len(mesh(os.path.join(work, "plate.1"))[1])
    p = run(work, "-Qpqu", "plate.poly")
    check(p.returncode == 0 and p.stderr == "", f"-pqu: exit {p.returncode}, {p.stderr!r}")
    points, triangles = mesh(os.path.join(work, "plate.1"))
    failing = [t for t in triangles
               if all(max(d2(points[t[0]], points[t[1]]), d2(points[t[1]], points[t[2]]), d2(points[t[2]], points[t[0]]))
                      > 0.05 * (v[0] ** 2 + v[1] ** 2) + 0.02 for v in (points[k] for k in t))]
    print(f"-pqu: {len(triangles)} triangles (-pq: {plain}; Triangle 1.6 -pqu: 258), {len(failing)} fail the stock test at every corner")
    check(not failing, f"-pqu: {len(failing)} triangles fail Triangle's stock -u test at all three corners, e.g. {failing[:3]}")
    check(len(triangles) > 2 * plain, f"-pqu: {len(triangles)} triangles, no more than -pq's {plain}: the test did not act")
    check(abs(len(triangles) - 258) <= 0.25 * 258, f"-pqu: {len(triangles)} triangles, not within 25% of Triangle's 258")
    p = run(work, "-Qpqu0.5", "plate.poly")
    points, triangles = mesh(os.path.join(work, "plate.1"))
    longest = max(math.sqrt(d2(points[a], points[b])) for t in triangles for a, b in ((t[0], t[1]), (t[1], t[2]), (t[2], t[0])))
    check(p.returncode == 0 and longest <= 0.5 * (1 + 1e-12), f"-pqu0.5: exit {p.returncode}, longest edge {longest}")


def poly_for_node(work):
    shutil.copy(os.path.join(INPUTS, "plate_markers.poly"), os.path.join(work, "plate.poly"))
    open(os.path.join(work, "plate.node"), "w").write("4\n2 0 0\n1 0 0\n2 4 0\n3 4 2\n4 0 2\n".replace("4\n2 0 0", "4 2 0 0"))
    p = run(work, "-Qp", "plate.node")
    check(p.returncode == 0, f"-p plate.node: {p.stderr}")
    points, triangles = mesh(os.path.join(work, "plate.1"))
    total = sum(area(points[a], points[b], points[c]) for a, b, c in triangles)
    print(f"-p plate.node: {len(points)} vertices, {len(triangles)} triangles, area {total}")
    check(abs(total - 7.5) < 1e-12 and len(points) == 12, f"-p plate.node: area {total}, {len(points)} vertices: not plate.poly's (7.5, 12)")
    check(os.path.exists(os.path.join(work, "plate.1.poly")), "-p plate.node wrote no .poly")
    os.remove(os.path.join(work, "plate.poly"))
    p = run(work, "-Qp", "plate.node")
    check(p.returncode == 1 and "plate.poly" in p.stderr, f"-p plate.node without plate.poly: exit {p.returncode}, {p.stderr!r}")


def ignorable_letters(work):
    shutil.copy(os.path.join(INPUTS, "plate_markers.poly"), os.path.join(work, "plate.poly"))
    p = run(work, "-pD", "plate.poly")
    d_points, d_triangles = mesh(os.path.join(work, "plate.1"))
    p = run(work, "-pL", "plate.poly")
    notices = [l for l in p.stderr.splitlines() if l]
    check(p.returncode == 0 and len(notices) == 1 and notices[0].startswith("deltri: -L: "), f"-pL: exit {p.returncode}, {p.stderr!r}")
    check(mesh(os.path.join(work, "plate.1")) == (d_points, d_triangles), "-pL: not the mesh of -pD")
    for letters in ("w", "W", "o3", "S2.5", "q."):
        p = run(work, f"-p{letters}", "plate.poly")
        notices = [l for l in p.stderr.splitlines() if l]
        check(p.returncode == 0 and len(notices) == 1 and notices[0].startswith(f"deltri: -{letters}"),
              f"-p{letters}: exit {p.returncode}, {p.stderr!r}")
    for letters in ("H", "?"):
        p = run(work, f"-p{letters}", "plate.poly")
        check(p.returncode == 0 and p.stdout.startswith("deltri: "), f"-p{letters}: exit {p.returncode}, {p.stdout[:80]!r}")


def dimension3(work):
    text = open(os.path.join(INPUTS, "plate_markers.poly")).read().replace("\n12 2 0 1\n", "\n12 3 0 1\n")
    open(os.path.join(work, "typo.poly"), "w").write(text)
    p = run(work, "-p", "typo.poly")
    line = text.split("\n").index("1 0 0 0") + 1
    check(p.returncode == 1 and p.stderr.startswith(f"typo.poly:{line}: ") and "dimension 3" in p.stderr and "must be 2" in p.stderr,
          f"dimension typo: exit {p.returncode}, {p.stderr!r}")
    check(sorted(os.listdir(work)) == ["typo.poly"], f"dimension typo wrote {os.listdir(work)}")


def messages(work):
    shutil.copy(os.path.join(DATA, "guitar.poly"), work)
    p = run(work, "-pV", "--triangle-messages", "guitar.poly")
    points, triangles = mesh(os.path.join(work, "guitar.1"))
    used = {k for t in triangles for k in t}
    print(f"guitar -p: .node {len(points)} vertices, {len(used)} in triangles")
    check(f"  Mesh vertices: {len(used)}\n" in p.stdout and len(used) < len(points), f"Mesh vertices is not {len(used)}")
    bounds = [1.5, 2, 2.5, 3, 4, 6, 10, 15, 25, 50, 100, 300, 1000, 10000, 100000]
    # Bin i holds ratios in (bounds[i-1], bounds[i]]. A ratio within 1e-9 of a bound (guitar.poly
    # has right triangles of ratio 2.5) may fall on either side in floating point: such a
    # triangle may be counted in either bin.
    low, high = [0] * 16, [0] * 16
    for t in triangles:
        a, b, c = (points[k] for k in t)
        ratio = max(d2(a, b), d2(b, c), d2(c, a)) / (2 * area(a, b, c))  # longest / (2 area / longest)
        lo = next((i for i, x in enumerate(bounds) if ratio <= x * (1 - 1e-9)), 15)
        hi = next((i for i, x in enumerate(bounds) if ratio <= x * (1 + 1e-9)), 15)
        if lo == hi:
            low[lo] += 1
        high[lo] += 1
        high[hi] += 1 if hi != lo else 0
    lines = p.stdout.split("  Triangle aspect ratio histogram:\n")[-1].split("\n")[:8]
    got = [0] * 16
    for i, l in enumerate(lines):
        left, right = l.split("|")
        got[i], got[i + 8] = int(left.split(":")[-1]), int(right.split(":")[-1])
    print(f"aspect-ratio histogram: {got} (recomputed, per bin at least {low}, at most {high})")
    check(all(l <= g <= h for l, g, h in zip(low, got, high)) and sum(got) == len(triangles),
          f"aspect-ratio histogram {got}, recomputed between {low} and {high}")


work = tempfile.mkdtemp(prefix="deltri-cli-")
{"stock_u": stock_u, "poly_for_node": poly_for_node, "ignorable_letters": ignorable_letters, "dimension3": dimension3,
 "messages": messages}[ITEM](work)
shutil.rmtree(work)
sys.exit(1 if failures else 0)
