#!/usr/bin/env python3
"""The --svg picture (issue 46): checked from the SVG's own coordinates against the .node, .ele
and .edge files of the same run.

- well-formed XML (Python's parser);
- one triangle path per .ele triangle; the drawing's bounding box has the aspect ratio of the
  triangles' bounding box in the .node coordinates (the frame is the mesh's, not that of vertices
  outside it);
- the viewBox holds every triangle corner, with at most a 3% margin beyond the mesh on each side
  except the legend's, and there no more than the legend and that margin;
- the legend's boxes (swatches, and texts measured with DejaVu Sans's advance widths) overlap
  neither each other nor the mesh, and lie inside the viewBox;
- every .edge edge with a non-zero marker is drawn in the colour of that marker's legend swatch,
  and the legend's count for each marker is the .edge file's.

usage: svg_picture.py DELTRI SOURCE_DIR
"""
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

DELTRI, SOURCE = sys.argv[1], sys.argv[2]
NS = "{http://www.w3.org/2000/svg}"
# DejaVu Sans advance widths in em (the usual sans-serif); anything else counts as a wide 0.75.
WIDTH = {" ": 0.318, ":": 0.337, ";": 0.337, "-": 0.361, "\u00b0": 0.5, ".": 0.318, ",": 0.318,
         "a": 0.613, "b": 0.635, "c": 0.550, "d": 0.635, "e": 0.615, "f": 0.352, "g": 0.635, "h": 0.634,
         "i": 0.278, "j": 0.278, "k": 0.579, "l": 0.278, "m": 0.974, "n": 0.634, "o": 0.612, "p": 0.635,
         "q": 0.635, "r": 0.411, "s": 0.521, "t": 0.392, "u": 0.634, "v": 0.592, "w": 0.818, "x": 0.592,
         "y": 0.592, "z": 0.525}
WIDTH.update({d: 0.636 for d in "0123456789"})
failures = []


def check(ok, what):
    if not ok:
        failures.append(what)
        if len(failures) <= 20:
            print("FAIL:", what)


def read_table(path):
    rows = []
    with open(path) as f:
        for line in f:
            line = line.split("#")[0].split()
            if line:
                rows.append(line)
    return rows


def numbers(d):
    return [int(v) for v in re.findall(r"-?\d+", d)]


def overlap(a, b):
    return a[0] < b[2] and b[0] < a[2] and a[1] < b[3] and b[1] < a[3]


def check_picture(name, svg_path, base):
    try:
        root = ET.parse(svg_path).getroot()
    except ET.ParseError as e:
        check(False, f"{name}: not well-formed XML: {e}")
        return
    node = read_table(base + ".node")
    points = {int(r[0]): (float(r[1]), float(r[2])) for r in node[1:]}
    ele = read_table(base + ".ele")
    triangles = [[int(v) for v in r[1:4]] for r in ele[1:]]
    corners = [points[v] for t in triangles for v in t]
    lo_x, hi_x = min(p[0] for p in corners), max(p[0] for p in corners)
    lo_y, hi_y = min(p[1] for p in corners), max(p[1] for p in corners)

    # The triangles: closed three-point subpaths in filled paths.
    drawn, tri_pts = 0, []
    edges = []  # (x0, y0, x1, y1, stroke) of the unfilled paths
    for path in root.iter(NS + "path"):
        d = path.get("d", "")
        if path.get("fill") != "none":
            for sub in d.split("M")[1:]:
                v = numbers(sub)
                check(len(v) == 6 and sub.strip().endswith("z"), f"{name}: triangle subpath {sub[:40]!r}")
                drawn += 1
                tri_pts += [(v[0], v[1]), (v[2], v[3]), (v[4], v[5])]
        else:
            for sub in d.split("M")[1:]:
                v = numbers(sub)
                if len(v) == 4:
                    edges.append((*v, path.get("stroke")))
    check(drawn == len(triangles), f"{name}: {drawn} triangles drawn, the .ele has {len(triangles)}")
    sx0, sx1 = min(p[0] for p in tri_pts), max(p[0] for p in tri_pts)
    sy0, sy1 = min(p[1] for p in tri_pts), max(p[1] for p in tri_pts)
    side = max(sx1 - sx0, sy1 - sy0)
    scale = side / max(hi_x - lo_x, hi_y - lo_y)
    check(abs((sx1 - sx0) - (hi_x - lo_x) * scale) <= 2 and abs((sy1 - sy0) - (hi_y - lo_y) * scale) <= 2,
          f"{name}: the drawing's box {sx1 - sx0} x {sy1 - sy0} is not the mesh's shape")

    vx, vy, vw, vh = (float(v) for v in root.get("viewBox").split())
    margin = 0.03 * side
    # The legend: swatches and texts, as boxes.
    legend = ([g for g in root.iter(NS + "g") if g.get("font-size") == "150"] or [None])[-1]
    check(legend is not None, f"{name}: no legend group")
    if legend is None:
        return
    size = float(legend.get("font-size"))
    boxes, swatches, texts = [], [], []
    for el in legend:
        if el.tag == NS + "rect":
            x, y, w, h = (float(el.get(k)) for k in ("x", "y", "width", "height"))
            boxes.append((x, y, x + w, y + h, "swatch"))
            swatches.append((x, y, x + w, y + h, el.get("fill")))
        elif el.tag == NS + "text":
            x, y, t = float(el.get("x")), float(el.get("y")), el.text or ""
            w = size * sum(WIDTH.get(c, 0.75) for c in t)
            boxes.append((x, y - 0.76 * size, x + w, y + 0.24 * size, t))
            texts.append((x, y, t))
    for i, a in enumerate(boxes):
        check(vx <= a[0] and a[2] <= vx + vw and vy <= a[1] and a[3] <= vy + vh, f"{name}: legend box {a} outside the viewBox")
        check(not overlap(a, (sx0, sy0, sx1, sy1)), f"{name}: legend box {a[4]!r} over the mesh")
        for b in boxes[i + 1:]:
            check(not overlap(a, b), f"{name}: legend boxes overlap: {a[4]!r} and {b[4]!r}")
    lx1 = max(b[2] for b in boxes)
    ly1 = max(b[3] for b in boxes)
    check(vx <= sx0 and sx1 <= vx + vw and vy <= sy0 and sy1 <= vy + vh, f"{name}: the viewBox cuts the mesh")
    check(sx0 - vx <= margin and sy0 - vy <= margin, f"{name}: more than 3% blank left or above the mesh")
    # The program sizes text at a uniform, wider-than-real character width: beyond a text, up
    # to a quarter of the legend's width more is allowed.
    slack = 0.25 * (lx1 - min(b[0] for b in boxes))
    check(vx + vw - max(sx1, lx1) <= margin + slack and vy + vh - max(sy1, ly1) <= margin,
          f"{name}: more than 3% blank beyond the mesh and the legend")
    beside, below = min(b[0] for b in boxes) > sx1, min(b[1] for b in boxes) > sy1
    check(beside or below, f"{name}: the legend is neither beside nor below the mesh")
    if beside:
        check(vy + vh - sy1 <= margin or ly1 > sy1, f"{name}: blank below the mesh")
    if below:
        check(vx + vw - sx1 <= margin or lx1 > sx1, f"{name}: blank right of the mesh")

    # Markers: legend entries "marker m: k edges", each with the swatch on its line.
    colour_of, count_of = {}, {}
    for x, y, t in texts:
        m = re.match(r"marker (-?\d+): (\d+) edges?$", t)
        if not m:
            continue
        swatch = [s for s in swatches if s[2] <= x and x - s[2] < 200 and s[1] <= y - 0.3 * size <= s[3]]
        check(len(swatch) == 1, f"{name}: {t!r} has {len(swatch)} swatches")
        if swatch:
            colour_of[int(m.group(1))] = swatch[0][4]
        count_of[int(m.group(1))] = int(m.group(2))
    drawn_at = {}
    for x0, y0, x1, y1, stroke in edges:
        drawn_at.setdefault((x0 + x1, y0 + y1), []).append(stroke)
    wanted = {}
    for r in read_table(base + ".edge")[1:]:
        marker = int(r[3])
        if marker == 0:
            continue
        wanted[marker] = wanted.get(marker, 0) + 1
        (ax, ay), (bx, by) = points[int(r[1])], points[int(r[2])]
        mx = sx0 + (ax - lo_x) * scale + sx0 + (bx - lo_x) * scale
        my = sy0 + (hi_y - ay) * scale + sy0 + (hi_y - by) * scale
        found = [s for dx in range(-3, 4) for dy in range(-3, 4)
                 for s in drawn_at.get((round(mx) + dx, round(my) + dy), [])]
        check(marker in colour_of and colour_of[marker] in found,
              f"{name}: edge {r[0]} (marker {marker}) drawn in {found}, its legend colour is {colour_of.get(marker)}")
    for marker, n in wanted.items():
        check(count_of.get(marker) == n, f"{name}: legend counts {count_of.get(marker)} edges of marker {marker}, the .edge {n}")
    check(len(set(colour_of[m] for m in wanted if m in colour_of)) == len(wanted),
          f"{name}: markers share a colour: {colour_of}")


def tall_strip(path):
    """A 1 x 30 strip: markers 1-4 on its sides, 5 and 6 on two slits inside."""
    pts = [(0, 0), (1, 0), (1, 30), (0, 30), (0.3, 5), (0.7, 5), (0.3, 20), (0.7, 20)]
    segs = [(1, 2, 1), (2, 3, 2), (3, 4, 3), (4, 1, 4), (5, 6, 5), (7, 8, 6)]
    with open(path, "w") as f:
        f.write(f"{len(pts)} 2 0 0\n" + "".join(f"{i + 1} {x} {y}\n" for i, (x, y) in enumerate(pts)))
        f.write(f"{len(segs)} 1\n" + "".join(f"{i + 1} {a} {b} {m}\n" for i, (a, b, m) in enumerate(segs)))
        f.write("0\n")


work = tempfile.mkdtemp(prefix="deltri-svg-")
try:
    for f in ("water.poly", "plate-markers.poly", "guitar.poly", "ukraine.node"):
        shutil.copy(os.path.join(SOURCE, "data", f), work)
    os.chdir(work)
    tall_strip("strip.poly")
    cases = [("water.poly", "-pq"), ("plate-markers.poly", "-pq30a0.002"), ("guitar.poly", "-pq"),
             ("ukraine.node", "-q"), ("strip.poly", "-pq"), ("strip.poly", "-pqa0.05")]
    for i, (inp, sw) in enumerate(cases):
        base = inp.rsplit(".", 1)[0]
        for old in os.listdir("."):
            if old.startswith(base + ".1."):
                os.remove(old)
        r = subprocess.run([DELTRI, sw + "eQ", f"--svg=p{i}.svg", inp], capture_output=True, text=True, timeout=300)
        check(r.returncode == 0, f"{inp} {sw}: exit {r.returncode} {r.stderr}")
        if r.returncode == 0:
            check_picture(f"{inp} {sw}", f"p{i}.svg", base + ".1")
finally:
    shutil.rmtree(work, ignore_errors=True)

print(f"{len(failures)} failures" if failures else "svg pictures: ok")
sys.exit(1 if failures else 0)
