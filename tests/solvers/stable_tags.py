#!/usr/bin/python3
"""Issue 46: changing one boundary marker must not move any other physical group's tag.

  stable_tags.py DELTRI

plate_markers.poly (markers 1-5, region attribute 10) is meshed with --msh; then hole B's marker 5
becomes 7 and it is meshed again. Asserted for both meshes:
  * every $PhysicalNames entry other than "marker 5"/"marker 7" has the same tag and name in both;
    "marker 7" is curve 7;
  * GetDP, selecting the domain by the documented rule (Region[1000000000]; with -A attribute 10 is
    Region[1000000010]; with --domain-tag=6 Region[6]), integrates the area 7.5 that the .poly's
    own coordinates give, and each marker's curve has the length its segments give;
  * --domain-tag=3 (marker 3's tag) is refused with status 2, naming the clash, and writes nothing.
Exits 77 (skipped) when getdp is not installed.
"""
import os
import re
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
DELTRI = os.path.abspath(sys.argv[1])
failures = []


def check(ok, message):
    if not ok:
        failures.append(message)
        print("FAIL:", message)


def read_poly(path):
    """Vertices, segments (a, b, marker) and the area (outer polygon minus the holes' squares)."""
    rows = [l.split("#")[0].split() for l in open(path)]
    rows = [r for r in rows if r]
    n = int(rows[0][0])
    points = {int(r[0]): (float(r[1]), float(r[2])) for r in rows[1:1 + n]}
    m = int(rows[1 + n][0])
    segments = [(int(r[1]), int(r[2]), int(r[3])) for r in rows[2 + n:2 + n + m]]
    return points, segments


def shoelace(points, segments, marker_set):
    """Signed area of the closed chain of the segments whose marker is in marker_set."""
    return sum(points[a][0] * points[b][1] - points[b][0] * points[a][1] for a, b, k in segments if k in marker_set) / 2


def lengths(points, segments):
    out = {}
    for a, b, k in segments:
        (x0, y0), (x1, y1) = points[a], points[b]
        out[k] = out.get(k, 0.0) + ((x1 - x0) ** 2 + (y1 - y0) ** 2) ** 0.5
    return out


def physical_names(path):
    text = open(path).read()
    block = text.split("$PhysicalNames\n")[1].split("$EndPhysicalNames")[0].splitlines()[1:]
    return {m.group(3): (int(m.group(1)), int(m.group(2))) for m in (re.match(r'(\d+) (\d+) "(.*)"', l) for l in block)}


def getdp(work, msh, domain, curve):
    for f in ("area.txt", "length.txt"):
        if os.path.exists(os.path.join(work, f)):
            os.remove(os.path.join(work, f))
    p = subprocess.run(["getdp", "area.getdp.pro", "-msh", msh, "-setnumber", "Domain", str(domain), "-setnumber", "Curve",
                        str(curve), "-solve", "Area", "-pos", "Report"], cwd=work, capture_output=True, text=True, timeout=120)
    if p.returncode != 0 or "Error" in p.stdout + p.stderr:
        check(False, f"getdp on {msh}: exit {p.returncode}\n{p.stdout[-1500:]}{p.stderr[-1500:]}")
        return None, None
    value = lambda f: float(open(os.path.join(work, f)).read().split()[-1])
    return value("area.txt"), value("length.txt")


def deltri(work, args):
    return subprocess.run([DELTRI, "-Q"] + args, cwd=work, capture_output=True, text=True)


def main():
    if shutil.which("getdp") is None:
        print("getdp is not installed: apt-get install getdp")
        sys.exit(77)
    work = tempfile.mkdtemp(prefix="deltri-tags-")
    shutil.copy(os.path.join(HERE, "area.getdp.pro"), work)
    original = open(os.path.join(HERE, "plate_markers.poly")).read()
    changed = re.sub(r"^(\d+ \d+ \d+) 5$", r"\1 7", original, flags=re.M)  # hole B: marker 5 -> 7
    check(changed.count(" 7\n") == 4, "the edit did not change hole B's four segments")
    names = {}
    for label, text in (("before", original), ("after", changed)):
        open(os.path.join(work, f"{label}.poly"), "w").write(text)
        points, segments = read_poly(os.path.join(work, f"{label}.poly"))
        area = shoelace(points, segments, {1, 2, 3}) - abs(shoelace(points, segments, {4})) - abs(shoelace(points, segments, {5, 7}))
        check(abs(area - 7.5) < 1e-12, f"{label}: the .poly's area is {area}, not 7.5")
        for switches, domain_name, domain_tag, extra in (("", "domain", 1000000000, []), ("A", "attribute 10", 1000000010, []),
                                                         ("", "domain", 6, ["--domain-tag=6"])):
            msh = f"{label}{switches}{len(extra)}.msh"
            p = deltri(work, [f"-pq30a0.05{switches}", f"--msh={msh}"] + extra + [f"{label}.poly"])
            check(p.returncode == 0, f"deltri -pq30a0.05{switches} {extra} {label}.poly: {p.stderr}")
            groups = physical_names(os.path.join(work, msh))
            names[(label, switches, len(extra))] = groups
            check(groups.get(domain_name) == (2, domain_tag), f"{msh}: {domain_name!r} is {groups.get(domain_name)}, the rule gives (2, {domain_tag})")
            for marker, length in lengths(points, segments).items():
                check(groups.get(f"marker {marker}") == (1, marker), f"{msh}: marker {marker} is {groups.get(f'marker {marker}')}")
                got_area, got_length = getdp(work, msh, domain_tag, marker)
                print(f"  {msh}: Region[{domain_tag}] area {got_area}, Region[{marker}] length {got_length} (expected {area}, {length})")
                check(got_area is not None and abs(got_area - area) < 1e-9, f"{msh}: GetDP's area of Region[{domain_tag}] is {got_area}, not {area}")
                check(got_length is not None and abs(got_length - length) < 1e-9, f"{msh}: GetDP's length of Region[{marker}] is {got_length}, not {length}")
    for key in {k[1:] for k in names}:
        before, after = names[("before",) + key], names[("after",) + key]
        kept = {n: t for n, t in before.items() if n != "marker 5"}
        check(kept == {n: t for n, t in after.items() if n != "marker 7"}, f"groups other than the changed marker moved: {before} -> {after}")
        check("marker 5" in before and after.get("marker 7") == (1, 7), f"the changed marker: {before} -> {after}")
    files = set(os.listdir(work))
    p = deltri(work, ["-pq30a0.05", "--msh=clash.msh", "--domain-tag=3", "before.poly"])
    check(p.returncode == 2 and "marker 3" in p.stderr and "--domain-tag=3" in p.stderr, f"--domain-tag=3: exit {p.returncode}, {p.stderr!r}")
    check(set(os.listdir(work)) == files, f"--domain-tag=3 wrote files: {set(os.listdir(work)) - files}")
    if failures:
        sys.exit(1)
    shutil.rmtree(work)
    print("stable tags: every group kept its tag; GetDP found the domain by the rule in all meshes")


main()
