#!/usr/bin/python3
"""deltri's single-file outputs read back by real readers, compared with the .node/.ele/.edge/.poly
of the same run (read here by a few lines of our own, not by deltri).

  check_formats.py DELTRI DATA_DIR INPUTS_DIR what...   (what: msh vtu svg json pipe strict)

.msh: meshio (python3-meshio) and gmsh itself (its binary rewrite and node data views read back);
.vtu: meshio; .svg: rsvg-convert renders it, the
PNG is decoded here and must be large and colourful, and the legend's counts must match the angles
computed from .node/.ele; JSON: parsed, counts and smallest angle against .node/.ele; pipe:
`cat X.poly | deltri -pq30 --msh=- - > a.msh` loads in gmsh and equals the file run's mesh.
Exits 1 on the first failed check (printing it), 0 when all hold.
"""
import json
import math
import os
import re
import shutil
import struct
import subprocess
import sys
import tempfile
import zlib

DELTRI, DATA, INPUTS = (os.path.abspath(a) for a in sys.argv[1:4])
WHAT = sys.argv[4:]

# What each check reads its files with, and the Debian package that has it.
NEEDS = {"msh": ["meshio", "gmsh"], "vtu": ["meshio"], "svg": ["rsvg-convert"], "pipe": ["meshio", "gmsh"]}
PACKAGE = {"meshio": "python3-meshio", "gmsh": "gmsh", "rsvg-convert": "librsvg2-bin"}


def skip_when_missing():
    """Exit 77 (CTest: skipped) naming what is missing and how to install it."""
    missing = []
    for tool in sorted({t for w in WHAT for t in NEEDS.get(w, [])}):
        if tool == "meshio":
            try:
                import meshio  # noqa: F401
            except ImportError:
                missing.append(tool)
        elif shutil.which(tool) is None:
            missing.append(tool)
    if missing:
        packages = " ".join(PACKAGE[t] for t in missing)
        print(f"SKIP: missing {', '.join(missing)}; install with: sudo apt-get install -y {packages}")
        sys.exit(77)


def fail(message):
    print("FAIL:", message)
    sys.exit(1)


def check(condition, message):
    if not condition:
        fail(message)


def data_lines(path):
    with open(path) as f:
        for line in f:
            line = line.split("#", 1)[0].split()
            if line:
                yield line


def read_node(path):
    lines = data_lines(path)
    n, _, na, nm = (int(x) for x in next(lines))
    pts, attrs, markers = [], [], []
    first = None
    for _ in range(n):
        t = next(lines)
        if first is None:
            first = int(t[0])
        pts.append((float(t[1]), float(t[2])))
        attrs.append([float(x) for x in t[3:3 + na]])
        markers.append(int(t[3 + na]) if nm else None)
    return first, pts, attrs, markers


def read_ele(path, first):
    lines = data_lines(path)
    n, nodes, na = (int(x) for x in next(lines))
    tris = []
    for _ in range(n):
        t = next(lines)
        tris.append((tuple(int(x) - first for x in t[1:1 + nodes]), [float(x) for x in t[1 + nodes:1 + nodes + na]]))
    return tris


def read_edges(path, first):
    lines = data_lines(path)
    n, nm = (int(x) for x in next(lines))
    return [((int(t[1]) - first, int(t[2]) - first), int(t[3]) if nm else None) for t in (next(lines) for _ in range(n))]


def read_poly_segments(path, first):
    lines = data_lines(path)
    next(lines)
    n, nm = (int(x) for x in next(lines))
    return [frozenset((int(t[1]) - first, int(t[2]) - first)) for t in (next(lines) for _ in range(n))]


def run(args, cwd, stdin=None, expect=0):
    p = subprocess.run([DELTRI] + args, cwd=cwd, stdin=stdin, capture_output=True)
    check(p.returncode == expect, f"deltri {' '.join(args)}: exit {p.returncode}, expected {expect}: {p.stderr.decode()}")
    return p


class Run:
    """deltri run in a fresh directory on a copy of the input; the Triangle files read back."""

    def __init__(self, source, switches, extra=()):
        self.dir = tempfile.mkdtemp(prefix="deltri-formats-")
        self.name = os.path.basename(source)
        shutil.copy(source, os.path.join(self.dir, self.name))
        self.switches = switches
        self.proc = run([a for a in (switches, "-e") if a] + list(extra) + [self.name], self.dir)
        base = os.path.join(self.dir, os.path.splitext(self.name)[0] + ".1")
        self.base = base
        self.first, self.points, self.vattrs, self.vmarkers = read_node(base + ".node")
        self.tris = read_ele(base + ".ele", self.first)
        self.edges = read_edges(base + ".edge", self.first)
        self.segments = set(read_poly_segments(base + ".poly", self.first)) if os.path.exists(base + ".poly") else set()
        count = {}
        for nodes, _ in self.tris:
            for i in range(3):
                e = frozenset((nodes[i], nodes[(i + 1) % 3]))
                count[e] = count.get(e, 0) + 1
        # The edges a single-file format must carry as line elements: boundary or segment.
        self.lines = {frozenset(e): m for e, m in self.edges if count[frozenset(e)] == 1 or frozenset(e) in self.segments}
        self.label = f"{self.name} {switches} {' '.join(extra)}"

    def path(self, ext):
        return self.base + ext

    def done(self):
        shutil.rmtree(self.dir)


def gmsh_order(nodes):
    """.ele node order (corners, midpoints opposite corners 1, 2, 3) -> Gmsh/VTK order (corners, midpoints of edges 12, 23, 31)."""
    return nodes if len(nodes) == 3 else (nodes[0], nodes[1], nodes[2], nodes[5], nodes[3], nodes[4])


def check_points(r, points, what):
    check(len(points) == len(r.points), f"{r.label}: {what} has {len(points)} points, the .node {len(r.points)}")
    for i, (p, q) in enumerate(zip(points, r.points)):
        check(p[0] == q[0] and p[1] == q[1] and p[2] == 0, f"{r.label}: {what} point {i} is {tuple(p)}, the .node says {q}")


def check_midpoint_coordinates(r, cells, what):
    for c in cells:
        ends = [(0, 1), (1, 2), (2, 0)] if len(c) == 6 else [(0, 1)]
        for k, (a, b) in enumerate(ends):
            m = c[len(c) // 2 + (k if len(c) == 6 else 0)] if len(c) == 6 else c[2]
            pa, pb, pm = r.points[c[a]], r.points[c[b]], r.points[m]
            check(pm == (0.5 * (pa[0] + pb[0]), 0.5 * (pa[1] + pb[1])), f"{r.label}: {what} cell {tuple(c)}: node {m} is not the midpoint of {c[a]}-{c[b]}")


def expected_cells(r):
    return sorted((gmsh_order(nodes), tuple(attrs[:1])) for nodes, attrs in r.tris)


def expected_tags(r, markers):
    """The documented rule (docs/formats.md, "Physical groups"): a marker from 1 to 999999999 is its
    own tag, a marker m from -147483647 to 0 is 2000000000 - m; the domain is 1000000000 and, with
    -A, an integer attribute a from 0 to 899999999 is 1000000000 + a; any other value the next tag
    from 1900000000 up, markers first, each in ascending order."""
    values = sorted(set(r.lines.values())) if markers else []
    attrs = sorted({a[0] for _, a in r.tris if a}) or [None]
    whole = lambda v, lo, hi: v == int(v) and lo <= v <= hi
    tags, other = {}, 1900000000
    for v in values:
        tag = v if whole(v, 1, 999999999) else 2000000000 - v if whole(v, -147483647, 0) else None
        if tag is None:
            tag, other = other, other + 1
        tags[("marker", v)] = int(tag)
    for a in attrs:
        tag = 1000000000 if a is None else 1000000000 + a if whole(a, 0, 899999999) else None
        if tag is None:
            tag, other = other, other + 1
        tags[("attribute", a)] = int(tag)
    return tags


def check_msh(r, quadratic, markers=True, msh=None):
    import meshio
    msh = msh or r.path(".msh")
    m = meshio.read(msh)
    tags = expected_tags(r, markers)
    for name, (tag, dim) in m.field_data.items():
        key = ("marker", int(name.split()[1])) if dim == 1 else ("attribute", None if name == "domain" else float(name.split()[1]))
        check(tags.get(key) == tag, f"{r.label} {os.path.basename(msh)}: physical group {name!r} has tag {tag}, the rule gives {tags.get(key)}")
    all_tags = [int(v[0]) for v in m.field_data.values()]
    check(len(all_tags) == len(set(all_tags)), f"{r.label}: physical tags shared between groups: {m.field_data}")
    check_points(r, m.points, ".msh")
    names = {tuple(v): k for k, v in m.field_data.items()}  # (tag, dim) -> name
    tri_type, line_type = ("triangle6", "line3") if quadratic else ("triangle", "line")
    got_tris, got_lines = [], {}
    for block, phys in zip(m.cells, m.cell_data["gmsh:physical"]):
        check(block.type in (tri_type, line_type), f"{r.label}: .msh has cells of type {block.type}")
        for cell, tag in zip(block.data, phys):
            name = names[(int(tag), 2 if block.type == tri_type else 1)]
            if block.type == tri_type:
                attr = () if name == "domain" else (float(name.split()[1]),)
                got_tris.append((tuple(int(x) for x in cell), attr))
            else:
                got_lines[frozenset(int(x) for x in cell[:2])] = int(name.split()[1])
                if quadratic:
                    check_midpoint_coordinates(r, [tuple(int(x) for x in cell)], ".msh line")
    check(sorted(got_tris) == expected_cells(r), f"{r.label}: the .msh triangles (nodes, attribute) differ from the .ele")
    if quadratic:
        check_midpoint_coordinates(r, [c for c, _ in got_tris], ".msh triangle")
    expected_lines = r.lines if markers else {}
    check(got_lines == expected_lines, f"{r.label}: the .msh line elements/markers differ from the boundary and segment edges of the .edge ({len(got_lines)} vs {len(expected_lines)})")
    if markers:
        check([int(x) for x in m.point_data["marker"]] == r.vmarkers, f"{r.label}: .msh node markers differ from the .node")
    for k in range(len(r.vattrs[0]) if r.vattrs else 0):
        check([float(x) for x in m.point_data[f"attribute {k + 1}"]] == [a[k] for a in r.vattrs], f"{r.label}: .msh node attribute {k + 1} differs")
    check_with_gmsh(r, msh, quadratic, markers, expected_lines)


def check_with_gmsh(r, msh, quadratic, markers, expected_lines):
    """Gmsh itself reads the file: no error, as many nodes and elements, and what it writes back
    (binary, so every double stays exact: the mesh, and each $NodeData view as a file of its own)
    holds the .node's coordinates, the .ele's triangles with their attributes' groups, the boundary
    and segment edges with their markers' groups, and the .node's markers and attributes. Gmsh may
    renumber nodes, so everything is compared by coordinates."""
    import meshio
    scratch = tempfile.mkdtemp(prefix="deltri-gmsh-")  # gmsh's files, apart from the run's
    again, script, views = (os.path.join(scratch, f) for f in ("again.msh", "read.geo", "view"))
    with open(script, "w") as f:
        f.write(f'Merge "{msh}";\nPostProcessing.SaveMesh = 0;\nFor i In {{0:PostProcessing.NbViews-1}}\n'
                f'  Save View[i] StrCat("{views}", Sprintf("%g", i), ".msh");\nEndFor\n')
    g = subprocess.run(["gmsh", script, "-0", "-bin", "-o", again], capture_output=True, text=True)
    log = g.stdout + g.stderr
    check(g.returncode == 0 and "Error" not in log, f"{r.label}: gmsh could not read the .msh:\n{log}")
    check(re.search(rf"\b{len(r.points)} nodes\b", log), f"{r.label}: gmsh did not see {len(r.points)} nodes:\n{log}")
    elements = len(r.tris) + len(expected_lines)
    check(re.search(rf"\b{elements} elements\b", log), f"{r.label}: gmsh did not see {elements} elements:\n{log}")
    label = f"{r.label} {os.path.basename(msh)}, as gmsh wrote it back"
    m = meshio.read(again)
    xyz = lambda p: (float(p[0]), float(p[1]), float(p[2]))
    # (From MSH 2.2 Gmsh writes back only the nodes that elements use, from 4.1 all of them, which
    # sit in the surface's node block; it read them all, as its log said.)
    used = {v for nodes, _ in r.tris for v in nodes} | {v for e in expected_lines for v in e}
    got = sorted(map(xyz, m.points))
    check(got in (sorted((r.points[v][0], r.points[v][1], 0.0) for v in used), sorted((x, y, 0.0) for x, y in r.points)),
          f"{label}: other node coordinates than the .node")
    names = {(int(v[0]), int(v[1])): k for k, v in m.field_data.items()}
    tri_type = "triangle6" if quadratic else "triangle"
    got_tris, got_lines = [], []
    for block, phys in zip(m.cells, m.cell_data["gmsh:physical"]):
        for cell, tag in zip(block.data, phys):
            corners = tuple(xyz(m.points[i]) for i in cell)
            if block.type == tri_type:
                name = names[(int(tag), 2)]
                got_tris.append((corners, () if name == "domain" else (float(name.split()[1]),)))
            else:
                got_lines.append((tuple(sorted(corners[:2])), int(names[(int(tag), 1)].split()[1])))
    at = lambda v: (r.points[v][0], r.points[v][1], 0.0)
    want_tris = [(tuple(at(v) for v in gmsh_order(nodes)), tuple(attrs[:1])) for nodes, attrs in r.tris]
    check(sorted(got_tris) == sorted(want_tris), f"{label}: the triangles (corners, attribute group) differ from the .ele")
    want_lines = [(tuple(sorted(at(v) for v in e)), marker) for e, marker in expected_lines.items()]
    check(sorted(got_lines) == sorted(want_lines), f"{label}: the lines (ends, marker group) differ from the .edge")
    # The $NodeData views: "marker" (unless -B), then "attribute 1", ... Gmsh writes each view's
    # values by node tag, and keeps deltri's tags (1, 2, ... in .node order); compared on the nodes
    # it wrote back (for the ones it dropped, it writes entries under meaningless tags).
    want = {"marker": [float(x) for x in r.vmarkers]} if markers else {}
    want.update({f"attribute {k + 1}": [a[k] for a in r.vattrs] for k in range(len(r.vattrs[0]) if r.vattrs else 0)})
    got = dict(gmsh_view(f"{views}{i}.msh") for i in range(len(want)) if os.path.exists(f"{views}{i}.msh"))
    check(sorted(got) == sorted(want), f"{label}: node data views {sorted(got)}, expected {sorted(want)}")
    for name, values in want.items():
        check({v + 1: got[name].get(v + 1) for v in used} == {v + 1: values[v] for v in used}, f"{label}: node data {name!r} differs from the .node")
    shutil.rmtree(scratch)


def gmsh_view(path):
    """(name, {node tag: value}) of the one-component $NodeData of a view Gmsh saved in binary MSH."""
    data = open(path, "rb").read()
    pos = data.index(b"$NodeData\n") + len(b"$NodeData\n")

    def line():
        nonlocal pos
        end = data.index(b"\n", pos)
        text, pos = data[pos:end].decode(), end + 1
        return text

    strings = [line() for _ in range(int(line()))]
    [line() for _ in range(int(line()))]
    ints = [int(line()) for _ in range(int(line()))]
    check(ints[1] == 1, f"{path}: a view of {ints[1]} components")
    values = {}
    for k in range(ints[2]):
        tag, value = struct.unpack_from("<id", data, pos + 12 * k)
        values[tag] = value
    return strings[0].strip().strip('"'), values


def check_vtu(r, quadratic, markers=True, vtu=None):
    import meshio
    m = meshio.read(vtu or r.path(".vtu"))
    check_points(r, m.points, ".vtu")
    tri_type, line_type = ("triangle6", "line3") if quadratic else ("triangle", "line")
    got_tris, got_lines = [], {}
    for i, block in enumerate(m.cells):
        check(block.type in (tri_type, line_type), f"{r.label}: .vtu has cells of type {block.type}")
        for j, cell in enumerate(block.data):
            cell = tuple(int(x) for x in cell)
            if block.type == tri_type:
                attr = (float(m.cell_data["attribute_1"][i][j]),) if "attribute_1" in m.cell_data else ()
                got_tris.append((cell, attr))
                if markers:
                    check(int(m.cell_data["marker"][i][j]) == 0, f"{r.label}: .vtu triangle marker is not 0")
            else:
                got_lines[frozenset(cell[:2])] = int(m.cell_data["marker"][i][j])
    check(sorted(got_tris) == expected_cells(r), f"{r.label}: the .vtu triangles (nodes, attribute) differ from the .ele")
    if quadratic:
        check_midpoint_coordinates(r, [c for c, _ in got_tris], ".vtu triangle")
    check(got_lines == (r.lines if markers else {}), f"{r.label}: the .vtu line cells/markers differ from the .edge")
    if markers:
        check([int(x) for x in m.point_data["marker"]] == r.vmarkers, f"{r.label}: .vtu point markers differ from the .node")
    else:
        check("marker" not in m.point_data, f"{r.label}: .vtu has markers despite -B")


def png_pixels(path):
    """Decodes an 8-bit RGB/RGBA, non-interlaced PNG (what rsvg-convert writes)."""
    data = open(path, "rb").read()
    check(data[:8] == b"\x89PNG\r\n\x1a\n", f"{path} is not a PNG")
    pos, idat = 8, b""
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height, depth, colour, _, _, interlace = struct.unpack(">IIBBBBB", body)
            check(depth == 8 and colour in (2, 6) and interlace == 0, f"{path}: unexpected PNG kind")
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    bpp = 4 if colour == 6 else 3
    raw, stride = zlib.decompress(idat), width * bpp
    rows, prev = [], bytearray(stride)
    for y in range(height):
        f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - bpp] if i >= bpp else 0
            b = prev[i]
            c = prev[i - bpp] if i >= bpp else 0
            if f == 1:
                line[i] = (line[i] + a) & 255
            elif f == 2:
                line[i] = (line[i] + b) & 255
            elif f == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(bytes(line))
        prev = line
    return width, height, bpp, rows


def smallest_angle(p, q, s):
    def at(a, b, c):
        ux, uy, vx, vy = b[0] - a[0], b[1] - a[1], c[0] - a[0], c[1] - a[1]
        return math.atan2(abs(ux * vy - uy * vx), ux * vx + uy * vy)
    return math.degrees(min(at(p, q, s), at(q, s, p), at(s, p, q)))


def check_svg(r):
    svg = r.path(".svg")
    text = open(svg, encoding="utf-8").read()
    # Compact: a handful of <path> elements whatever the size of the mesh.
    check(text.count("<path") <= 8, f"{r.label}: {text.count('<path')} <path> elements in the SVG")
    # The legend counts triangles per 10-degree shade; recount from the .node/.ele.
    counts = [0] * 6
    for nodes, _ in r.tris:
        counts[min(int(smallest_angle(*(r.points[v] for v in nodes[:3])) / 10), 5)] += 1
    legend = [int(x) for x in re.findall(r"\u00b0: (\d+)</text>", text)]
    check(legend == counts, f"{r.label}: SVG legend {legend}, angles from .node/.ele give {counts}")
    png = r.path(".png")
    p = subprocess.run(["rsvg-convert", "-o", png, svg], capture_output=True, text=True)
    check(p.returncode == 0, f"{r.label}: rsvg-convert failed: {p.stderr}")
    width, height, bpp, rows = png_pixels(png)
    check(width >= 500 and height >= 100, f"{r.label}: the picture is only {width} x {height}")
    colours, painted = set(), 0
    for row in rows:
        for i in range(0, len(row), bpp):
            px = row[i:i + 3]
            colours.add(px)
            painted += px != b"\xff\xff\xff"
    check(len(colours) >= 4, f"{r.label}: the picture has only {len(colours)} colours")
    check(painted > 0.05 * width * height, f"{r.label}: only {painted} of {width * height} pixels are not white")
    print(f"  {r.label}: {width} x {height} PNG, {len(colours)} colours, {100 * painted // (width * height)}% painted, {os.path.getsize(svg)} bytes of SVG")


def check_json(r, extra_files):
    report = json.load(open(r.path(".json")))
    check(report["mesh"]["triangles"] == len(r.tris), f"{r.label}: JSON says {report['mesh']['triangles']} triangles, the .ele has {len(r.tris)}")
    check(report["mesh"]["edges"] == len(r.edges), f"{r.label}: JSON edges differ from the .edge")
    angles = [smallest_angle(*(r.points[v] for v in nodes[:3])) for nodes, _ in r.tris]
    check(abs(report["quality"]["smallest_angle"] - min(angles)) < 1e-9, f"{r.label}: JSON smallest angle {report['quality']['smallest_angle']}, computed {min(angles)}")
    written = sorted(os.path.basename(f) for f in report["files"])
    present = sorted(f for f in os.listdir(r.dir) if f != r.name and not f.endswith(extra_files))
    check(written == present, f"{r.label}: JSON lists {written}, the directory has {present}")
    check(report["exit_status"] == 0 and report["warnings"] == [], f"{r.label}: JSON exit status or warnings unexpected")
    for stage in ("read", "Delaunay"):
        check(report["seconds"][stage] >= 0, f"{r.label}: no {stage} time")


def rerun(r, extra):
    """The same run again in r's directory with other long options (the mesh is deterministic)."""
    run([a for a in (r.switches, "-e") if a] + extra + [r.name], r.dir)


def main():
    skip_when_missing()
    guitar, plate = os.path.join(DATA, "guitar.poly"), os.path.join(INPUTS, "plate.poly")
    water, ukraine = os.path.join(DATA, "water.poly"), os.path.join(DATA, "ukraine.node")
    attrs = os.path.join(INPUTS, "sq_attr.node")
    cases = [(plate, "-pA"), (plate, "-pAo2"), (plate, "-pq30a0.05A"), (guitar, "-p"), (guitar, "-pjo2"),
             (guitar, "-pz"), (guitar, "-pB"), (water, "-pA"), (ukraine, "-o2"), (attrs, "-qo2"), (attrs, "-B")]
    if "msh" in WHAT or "vtu" in WHAT:
        for source, switches in cases:
            r = Run(source, switches, ["--msh", "--vtu"])
            if "msh" in WHAT:
                check_msh(r, "o2" in switches, "B" not in switches)
                # Every version and encoding of the same mesh.
                for fmt in ("2.2,binary", "4.1", "4.1,binary"):
                    path = r.path("." + fmt.replace(",", "-") + ".msh")
                    rerun(r, [f"--msh={path}", f"--msh-format={fmt}"])
                    check_msh(r, "o2" in switches, "B" not in switches, path)
            if "vtu" in WHAT:
                check_vtu(r, "o2" in switches, "B" not in switches)
                path = r.path(".binary.vtu")
                rerun(r, [f"--vtu={path}", "--vtu-format=binary"])
                check_vtu(r, "o2" in switches, "B" not in switches, path)
            print(f"  {r.label}: {len(r.points)} nodes, {len(r.tris)} triangles, {len(r.lines)} boundary/segment edges agree")
            r.done()
    if "svg" in WHAT:
        for source, switches, extra in [(plate, "-pq30a0.05", ["--svg", "--svg-numbers"]), (guitar, "-pq30a0.02", ["--svg"]),
                                        (ukraine, "", ["--svg"])]:
            r = Run(source, switches, extra)
            check_svg(r)
            r.done()
    if "json" in WHAT:
        for source, switches in [(guitar, "-pq30"), (plate, "-pA")]:
            r = Run(source, switches, ["--json"])
            check_json(r, (".png",))
            print(f"  {r.label}: JSON report agrees with .node/.ele/.edge")
            r.done()
    if "strict" in WHAT:
        work = tempfile.mkdtemp(prefix="deltri-formats-")
        shutil.copy(guitar, work)
        p = run(["-pq30S", "--strict", "--json", "guitar.poly"], work, expect=3)
        report = json.load(open(os.path.join(work, "guitar.1.json")))
        check(report["exit_status"] == 3 and report["quality"]["triangles_missing_bounds"] > 0, "--strict: the JSON does not report the missed bounds")
        check(os.path.exists(os.path.join(work, "guitar.1.ele")), "--strict: the mesh was not written")
        run(["-pq30", "--strict", "guitar.poly"], work, expect=0)
        print(f"  --strict: exit 3 with {report['quality']['triangles_missing_bounds']} triangles missing the bound, 0 when met")
        shutil.rmtree(work)
    if "pipe" in WHAT:
        # The acceptance recipe, verbatim through a shell, then compared with a file run.
        r = Run(guitar, "-pq30", ["--msh"])
        sh = f"cat '{guitar}' | '{DELTRI}' -pq30 --msh=- - > a.msh"
        p = subprocess.run(["sh", "-c", sh], cwd=r.dir, capture_output=True, text=True)
        check(p.returncode == 0, f"{sh}: exit {p.returncode}: {p.stderr}")
        check("wrote standard output" in p.stderr, f"{sh}: the summary is not on stderr: {p.stderr!r}")
        check(open(os.path.join(r.dir, "a.msh"), "rb").read() == open(r.path(".msh"), "rb").read(), "the piped .msh differs from the file run's")
        shutil.copy(os.path.join(r.dir, "a.msh"), r.path(".msh"))
        check_msh(r, False)
        check(sorted(os.listdir(r.dir)) == sorted([r.name, "a.msh", "guitar.1.node", "guitar.1.ele", "guitar.1.poly", "guitar.1.edge", "guitar.1.msh"]),
              f"the pipe wrote files: {os.listdir(r.dir)}")
        print(f"  {sh}: gmsh and meshio read it; equal to the file run ({len(r.tris)} triangles)")
        r.done()
    print("check_formats: ok")


main()
