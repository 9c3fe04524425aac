#!/usr/bin/python3
"""A real solver on deltri's meshes, read straight from deltri's .msh in the format it reads natively.

  poisson.py DELTRI getdp|freefem [old-tag-rule]

-Laplace(u) = f on the L-shaped domain of lshape.poly with u = sin(pi x) cos(pi y) + x y, Dirichlet on
segment marker 1 and Neumann on markers 2 and 3, meshed by deltri -pq30a<A> at four successively
halved area bounds. Asserted, from the solver's own output:
  * every marker arrived as its own boundary region: the lengths the solver integrates over
    regions 1, 2, 3 are 4, 2, 2 (the true lengths), and the domain, region 1000000000, has area 3;
  * the observed L2 convergence rate of P1 elements lies in [1.8, 2.2];
  * P2 gives a rate above 2.6: GetDP on deltri's -o2 (6-node) meshes, FreeFem++ (whose gmshload
    reads 3-node triangles only) with its P2 space on the linear meshes.
The rate is the least-squares slope of log(error) against log(h), h = sqrt(area / triangles).
Exits 77 (skipped) when the solver is not installed.

With old-tag-rule, the test of the test: every mesh (MSH 2.2 ASCII then) has its domain moved to
physical tag 1 as the rule before issue 18 tagged it (surfaces numbered apart from the lines, so
marker 1 and the domain shared tag 1), and the run must fail on the regions check: exit 0 when it
does, 1 when the test passes or fails for another reason.
"""
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
DELTRI, SOLVER = os.path.abspath(sys.argv[1]), sys.argv[2]
OLD_TAG_RULE = sys.argv[3:] == ["old-tag-rule"]
BOUNDS = [0.01, 0.005, 0.0025, 0.00125]
LENGTHS = {1: 4.0, 2: 2.0, 3: 2.0}
AREA = 3.0


class Failure(Exception):
    def __init__(self, message, regions=False):
        super().__init__(message)
        self.regions = regions  # the regions check failed (what the old tag rule must cause)


def fail(message, regions=False):
    raise Failure(message, regions)


def old_tag_rule(path):
    """Rewrites an MSH 2.2 ASCII file to the tag rule before issue 18: the domain is surface 1."""
    lines, section = open(path).read().split("\n"), None
    for i, line in enumerate(lines):
        if line.startswith("$"):
            section = line
            continue
        fields = line.split()
        if section == "$PhysicalNames" and len(fields) == 3 and fields[0] == "2":
            lines[i] = '2 1 "domain"'
        elif section == "$Elements" and len(fields) > 3 and fields[1] in ("2", "9"):
            fields[3] = "1"
            lines[i] = " ".join(fields)
    open(path, "w").write("\n".join(lines))


def mesh(work, area, switches, msh_format):
    if OLD_TAG_RULE:
        msh_format = "2.2"
    name = f"a{area}{switches}{msh_format.replace(',', '-')}.msh"
    p = subprocess.run([DELTRI, f"-pq30a{area}{switches}", "-Q", f"--msh={name}", f"--msh-format={msh_format}", "lshape.poly"],
                       cwd=work, capture_output=True, text=True)
    if p.returncode != 0:
        fail(f"deltri: {p.stderr}")
    if OLD_TAG_RULE:
        old_tag_rule(os.path.join(work, name))
    with open(os.path.join(work, "lshape.1.ele")) as f:
        triangles = int(f.readline().split()[0])
    return name, triangles


def getdp(work, msh):
    p = subprocess.run(["getdp", "poisson.getdp.pro", "-msh", msh, "-solve", "Poisson", "-pos", "Report"],
                       cwd=work, capture_output=True, text=True, timeout=120)
    if p.returncode != 0 or "Error" in p.stdout + p.stderr:
        fail(f"getdp on {msh}: exit {p.returncode}\n{p.stdout[-2000:]}{p.stderr[-2000:]}")
    value = lambda f: float(open(os.path.join(work, f)).read().split()[-1])
    return value("err2.txt"), value("area.txt"), {k: value(f"length{k}.txt") for k in LENGTHS}


def freefem(work, msh, order):
    env = dict(os.environ, FF_LOADPATH="/usr/lib/freefem++")
    p = subprocess.run(["FreeFem++", "-nw", "-ne", "poisson.freefem.edp", msh, str(order)],
                       cwd=work, capture_output=True, text=True, timeout=120, env=env)
    out = p.stdout + p.stderr
    found = dict(re.findall(r"RESULT (\w+) (.*)", out))
    if p.returncode != 0 or len(found) != 3:
        fail(f"FreeFem++ on {msh}: exit {p.returncode}\n{out[-3000:]}")
    area, total_area = (float(x) for x in found["area"].split(" of "))
    lengths, total = found["lengths"].split(" of ")
    lengths = dict(zip(LENGTHS, (float(x) for x in lengths.split())))
    # Every boundary edge carries exactly one of the labels: the three add up to the whole boundary.
    if abs(sum(lengths.values()) - float(total)) > 1e-9 or abs(area - total_area) > 1e-9:
        fail(f"FreeFem++ on {msh}: labels do not cover the boundary / region 1000000000 is not the whole domain: {found}", regions=True)
    return float(found["err2"]), area, lengths


def rate(hs, errors):
    xs, ys = [math.log(h) for h in hs], [math.log(e) for e in errors]
    mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
    return sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs)


def study(work, label, switches, msh_format, solve):
    hs, errors = [], []
    for area in BOUNDS:
        msh, triangles = mesh(work, area, switches, msh_format)
        err2, domain, lengths = solve(msh)
        if abs(domain - AREA) > 1e-9 or any(abs(lengths[k] - LENGTHS[k]) > 1e-9 for k in LENGTHS):
            fail(f"{label} -a{area}: regions arrived wrong: domain (region 1000000000) area {domain}, marker lengths {lengths}, expected {AREA} and {LENGTHS}", regions=True)
        hs.append(math.sqrt(AREA / triangles))
        errors.append(math.sqrt(err2))
        print(f"  {label} -pq30a{area}{switches} --msh-format={msh_format}: {triangles} triangles, L2 error {errors[-1]:.4e}")
    r = rate(hs, errors)
    print(f"  {label}: observed L2 rate {r:.3f}")
    return r


def main():
    program = {"getdp": "getdp", "freefem": "FreeFem++"}[SOLVER]
    if shutil.which(program) is None or (SOLVER == "freefem" and not os.path.exists("/usr/lib/freefem++/gmsh.so")):
        print(f"{program} (with its gmsh plugin) is not installed: apt-get install getdp freefem++ libfreefem++")
        sys.exit(77)
    work = tempfile.mkdtemp(prefix="deltri-solver-")
    for f in ("lshape.poly", "poisson.getdp.pro", "poisson.freefem.edp"):
        shutil.copy(os.path.join(HERE, f), work)
    if SOLVER == "getdp":
        p1 = study(work, "GetDP P1", "", "2.2", lambda m: getdp(work, m))
        p2 = study(work, "GetDP P2", "o2", "2.2,binary", lambda m: getdp(work, m))
    else:
        p1 = study(work, "FreeFem++ P1", "", "2.2", lambda m: freefem(work, m, 1))
        p2 = study(work, "FreeFem++ P2", "", "2.2", lambda m: freefem(work, m, 2))
    if not 1.8 <= p1 <= 2.2:
        fail(f"P1 L2 rate {p1:.3f} outside [1.8, 2.2]")
    if not p2 > 2.6:
        fail(f"P2 L2 rate {p2:.3f} not above 2.6")
    shutil.rmtree(work)


try:
    main()
except Failure as failure:
    print("FAIL:", failure)
    if OLD_TAG_RULE and failure.regions:
        print("poisson: with the old tag rule the test fails, as it must")
        sys.exit(0)
    sys.exit(1)
if OLD_TAG_RULE:
    print("FAIL: the test passed with the old tag rule")
    sys.exit(1)
print("poisson: ok")
