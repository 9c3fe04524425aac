#!/usr/bin/python3
"""The guarantees of Shewchuk 2001 for --algorithm=ruppert|chew and --interior-bound, checked on
deltri's output files with nothing deltri reports about quality.

    paper_algorithms.py eligible INPUT...                 the inputs whose input angles are all >= 60
    paper_algorithms.py ruppert DELTRI INPUT              Sec. 3 at -pDq20.7
    paper_algorithms.py interior DELTRI INPUT ALG N Q     Sec. 7.2, strategy N, -q Q, --algorithm=ALG
    paper_algorithms.py fewer DELTRI INPUT Q              Sec. 4.1: Chew makes fewer triangles than Ruppert
    paper_algorithms.py refusals DELTRI INPUT             the combinations the paper rules out: exit 2,
                                                          one line on stderr, no output file
    paper_algorithms.py conformity DELTRI INPUT           -pDq20.7 on any input: edges left not Delaunay
                                                          are warned of, counted exactly, and --strict fails
    paper_algorithms.py sure_fire DELTRI DEG SWITCHES...  two segments from one vertex DEG degrees apart in a
                                                          box: the guard stops the ping-pong (issue 16)
    paper_algorithms.py chew_wedge DELTRI DEG Q [LEN]     the same box: Chew at -pqQ makes at most 4 times
                                                          Ruppert's triangles, no edge under 1/4 of Ruppert's
                                                          (the second segment LEN long, 0.9 by default)
    paper_algorithms.py chew_crossing DELTRI DEG Q        the same for two segments crossing at DEG degrees
    paper_algorithms.py near_limit DELTRI INPUT ALG       ALG at -pq34, past what it reaches: no worse than
                                                          its -pq30 mesh, at most 10 times its triangles,
                                                          every miss warned of

Every mode first checks that the input has no two segments meeting at an angle under 60 degrees and
no segments that cross or touch inside (the paper's condition), from the input file itself; each run
is made twice and must give the same bytes; the run must exit 0.
- ruppert: the mesh is truly Delaunay, checked exactly (rational arithmetic on the doubles written:
  for every edge between two triangles, segments included, the far vertex is not strictly inside the
  other's circumcircle), and has no angle under 20.7 degrees (B = sqrt 2).
- interior: a vertex lies in a segment interior when it is an end of an output .poly segment and not
  an input vertex (exact coordinates); the output segments must lie on the input segments (checked).
  Strategy 1: every triangle with no such vertex has all angles >= 30, every other one >= Q.
  Strategy 2: every angle >= Q, and every triangle with an angle under 30 has a circumcircle that
  meets an input segment (the paper: such triangles "only occur near segments").
- fewer: at -pqQ, Chew's mesh (constrained Delaunay, checked exactly with the segments as
  constraints, no angle under Q) has fewer triangles than Ruppert's.
- conformity (no condition on the input angles): Ruppert at -pDq20.7, its output checked exactly as
  above; N edges not Delaunay (segments included) must come with the warning "N subsegments are not
  Delaunay" (the same N) and exit 3 under --strict; none must come with no such warning and exit 0
  under --strict (issue 22: these meshes used to end with exit 0 and no word of it).
- sure_fire (issue 16): the box [-1, 2] x [-1, 1] with two segments from (0, 0), of lengths 1 and 0.9,
  DEG degrees apart. Ruppert's algorithm ping-pongs between them (Sec. 3.3, 5): at 5 degrees it used
  to run to the Steiner cap, at 0.1 until the memory was gone. The run must exit 0 within a generous
  time limit (a guard against a hang, not a measurement) and under a 4 GiB address-space limit; its
  --json report must name the sure-fire rule among the reasons and count its refusals, and not the
  Steiner cap; the mesh must be constrained Delaunay with counter-clockwise triangles (exact) and
  cover the box exactly (the triangles' areas, exact, sum to 6).
- chew_wedge (issue 22): the sure_fire box, Chew's and Ruppert's algorithms at -pqQ. Away from the wedge
  both grade the mesh to the local feature size (Sec. 3.2, 4.2: each within a constant of lfs), and in the
  wedge the sure-fire rule must stop both at the scale where a split would be narrower than its ancestor
  across the wedge; so their meshes differ by a constant factor, whatever the angle. Chew's must have at
  most 4 times Ruppert's triangles and no edge shorter than a quarter of Ruppert's shortest. When the
  rule looked only at the newer end of the requesting triangle's shortest edge, Chew refined the wedge
  down to the floor, about ln(R / r) / phi splits: at 1 degree 1,058 triangles against Ruppert's 53, at
  0.01 degrees 162,343 against 115 (shortest edge 8.6e-10 against 1.8e-4). Both meshes are checked as
  in sure_fire (constrained Delaunay, exactly; the box covered). With LEN 1 the wedge's far end is closed
  by two input vertices phi apart; Chew then filled the strip between the pieces down to the floor through
  a free vertex inside it, which the rule did not see (199,368 triangles against Ruppert's 121 at 0.01
  degrees, -pq20), until the vertex a split's insertion radius is measured to counted as its ancestor.
- chew_crossing (issue 22): the same box and comparison with two segments of length about 1 crossing at
  (0.5, 0) at DEG degrees, their ends paired at x = 0 and 1 (as in tests/e2e/inputs/tiny_crossing.poly):
  each thin wedge at the crossing is such a strip; Chew made 2,686 and 356,966 triangles at 1 and 0.01
  degrees, -pq20 (Ruppert 120 and 246).
- near_limit (issue 42): Ruppert's and Chew's algorithms at -pq34 used to run to the Steiner cap on river
  and airfoil_exterior (708,018 and 251,157 triangles, smallest angles 0.54 and 0.24 degrees). A mode run
  past what it reaches must stop with a mesh no worse than its -pq30 one: the -pq34 mesh's smallest angle
  at least the -pq30 mesh's, at most 10 times its triangles, and if any triangle is under 34 degrees the
  run (without -Q) prints a warning that counts the triangles that miss the bound (the same number).
Angles are computed in doubles with a tolerance of 1e-9 degrees.
"""
import json
import re
import math
import os
import resource
import shutil
import subprocess
import sys
import tempfile
from fractions import Fraction

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'tools'))
from exact_delaunay_check import incircle, orient  # noqa: E402 (exact, on Fractions)
from exact_delaunay_check import numbers as rows  # noqa: E402 (the rows of a Triangle file, comments cut)

TOLERANCE = 1e-9


def read_poly(path):
    """Vertices (id -> (x, y) floats) and segments (pairs of ids) of a .poly, or of a .node (no segments)."""
    r = rows(path)
    n = int(r[0][0])
    src = r
    if path.endswith('.poly') and n == 0:
        src = rows(path[:-5] + '.node')
        n = int(src[0][0])
    pts = {int(x[0]): (float(x[1]), float(x[2])) for x in src[1:1 + n]}
    if not path.endswith('.poly'):
        return pts, []
    at = 1 + (int(r[0][0]))
    m = int(r[at][0])
    segs = [(int(x[1]), int(x[2])) for x in r[at + 1:at + 1 + m]]
    return pts, segs


def angle_at(w, a, b):
    ux, uy = a[0] - w[0], a[1] - w[1]
    vx, vy = b[0] - w[0], b[1] - w[1]
    return math.degrees(math.atan2(abs(ux * vy - uy * vx), ux * vx + uy * vy))


def smallest_input_angle(pts, segs):
    """The smallest angle between two segments at a common end; 0 when segments cross or touch inside."""
    ends = {}
    for a, b in segs:
        if pts[a] == pts[b]:
            continue
        ends.setdefault(pts[a], []).append(pts[b])
        ends.setdefault(pts[b], []).append(pts[a])
    smallest = 180.0
    for w, others in ends.items():
        for i in range(len(others)):
            for j in range(i + 1, len(others)):
                smallest = min(smallest, angle_at(w, others[i], others[j]))
    exact = [(tuple(map(Fraction, pts[a])), tuple(map(Fraction, pts[b]))) for a, b in segs if pts[a] != pts[b]]
    vertices = {tuple(map(Fraction, p)) for p in pts.values()}
    if len(exact) > 3000:
        return 0.0  # too large to check for crossings here: not used
    for i, (p, q) in enumerate(exact):
        for v in vertices:  # a vertex inside a segment splits it into two at 180 degrees: fine, but
            if v != p and v != q and orient(p, q, v) == 0 and between(p, q, v):
                smallest = min(smallest, 180.0)  # ... the pieces are what the mesher sees
        for (r, s) in exact[i + 1:]:
            if len({p, q, r, s}) < 4:
                continue
            if proper_cross(p, q, r, s):
                return 0.0
    return smallest


def between(p, q, v):
    return min(p[0], q[0]) <= v[0] <= max(p[0], q[0]) and min(p[1], q[1]) <= v[1] <= max(p[1], q[1])


def proper_cross(p, q, r, s):
    o1, o2, o3, o4 = orient(p, q, r), orient(p, q, s), orient(r, s, p), orient(r, s, q)
    if o1 * o2 < 0 and o3 * o4 < 0:
        return True
    for (a, b, c, o) in ((p, q, r, o1), (p, q, s, o2), (r, s, p, o3), (r, s, q, o4)):
        if o == 0 and between(a, b, c) and c != a and c != b:
            return True  # an end of one segment inside the other
    return False


def run(deltri, inp, switches, work):
    """Runs deltri twice; returns the output base path. Fails on a non-zero exit or differing bytes."""
    outputs = []
    for k in range(2):
        d = os.path.join(work, 'run%d' % k)
        shutil.rmtree(d, ignore_errors=True)
        os.makedirs(d)
        shutil.copy(inp, d)
        if inp.endswith('.poly') and os.path.exists(inp[:-5] + '.node'):
            shutil.copy(inp[:-5] + '.node', d)
        name = os.path.basename(inp)
        r = subprocess.run([deltri] + switches + ['-Q', name], cwd=d, capture_output=True, text=True, timeout=900)
        if r.returncode != 0:
            raise SystemExit('FAIL: %s %s: exit %d: %s' % (name, ' '.join(switches), r.returncode, r.stderr.strip()))
        base = os.path.join(d, name.rsplit('.', 1)[0] + '.1')
        outputs.append(base)
    for ext in ('.node', '.ele', '.poly'):
        a, b = outputs[0] + ext, outputs[1] + ext
        if os.path.exists(a) and open(a, 'rb').read() != open(b, 'rb').read():
            raise SystemExit('FAIL: %s %s: two runs wrote different %s files' % (inp, ' '.join(switches), ext))
    return outputs[0]


def read_mesh(base):
    r = rows(base + '.node')
    pts = {int(x[0]): (float(x[1]), float(x[2])) for x in r[1:1 + int(r[0][0])]}
    r = rows(base + '.ele')
    tris = [tuple(int(v) for v in x[1:4]) for x in r[1:1 + int(r[0][0])]]
    segs = []
    if os.path.exists(base + '.poly'):
        r = rows(base + '.poly')
        at = 1 + int(r[0][0])
        segs = [(int(x[1]), int(x[2])) for x in r[at + 1:at + 1 + int(r[at][0])]]
    return pts, tris, segs


def min_angle(pts, t):
    a, b, c = pts[t[0]], pts[t[1]], pts[t[2]]
    return min(angle_at(a, b, c), angle_at(b, c, a), angle_at(c, a, b))


def delaunay_faults(pts, tris, constrained):
    """Exact: triangles counter-clockwise, and every edge between two triangles locally Delaunay
    (segments included unless they are in `constrained`)."""
    exact = {k: (Fraction(x), Fraction(y)) for k, (x, y) in pts.items()}
    edges, faults = {}, []
    for (a, b, c) in tris:
        if orient(exact[a], exact[b], exact[c]) <= 0:
            faults.append('triangle %d %d %d not counter-clockwise' % (a, b, c))
        for (u, v, w) in ((a, b, c), (b, c, a), (c, a, b)):
            edges[(u, v)] = w
    for (u, v), w in edges.items():
        other = edges.get((v, u))
        if other is None or u > v or frozenset((u, v)) in constrained:
            continue
        if incircle(exact[u], exact[v], exact[w], exact[other]) > 0:
            faults.append('edge %d-%d not Delaunay: vertex %d inside the circumcircle of %d %d %d' % (u, v, other, u, v, w))
    return faults


def require_eligible(inp):
    pts, segs = read_poly(inp)
    m = smallest_input_angle(pts, segs)
    if m < 60.0 - TOLERANCE:
        raise SystemExit('FAIL: %s: not a test input for the paper\'s bounds: smallest input angle %.4f < 60' % (inp, m))
    return pts, segs


def check_ruppert(deltri, inp, work):
    require_eligible(inp)
    base = run(deltri, inp, ['-pDq20.7', '--algorithm=ruppert'], work)
    pts, tris, _ = read_mesh(base)
    faults = delaunay_faults(pts, tris, set())
    worst = min(min_angle(pts, t) for t in tris)
    if worst < 20.7 - TOLERANCE:
        faults.append('smallest angle %.6f < 20.7' % worst)
    report(faults, '%s ruppert -pDq20.7: %d triangles, truly Delaunay, smallest angle %.4f' % (inp, len(tris), worst))


def segment_interior(pts, segs, inputs, input_segs):
    """The output vertices in a segment interior: ends of output segments that are not input vertices;
    each must lie on an input segment (within rounding: split points are rounded doubles)."""
    input_points = set(inputs.values())
    interior = {v for s in segs for v in s if pts[v] not in input_points}
    for v in interior:
        x, y = pts[v]
        near = False
        for a, b in input_segs:
            (ax, ay), (bx, by) = inputs[a], inputs[b]
            length = math.hypot(bx - ax, by - ay)
            cross = abs((bx - ax) * (y - ay) - (by - ay) * (x - ax)) / length
            along = ((x - ax) * (bx - ax) + (y - ay) * (by - ay)) / length
            scale = max(abs(ax), abs(ay), abs(bx), abs(by), length)
            if cross <= 1e-12 * scale and -1e-12 * scale < along < length * (1 + 1e-12):
                near = True
                break
        if not near:
            raise SystemExit('FAIL: output segment vertex %d %s lies on no input segment' % (v, pts[v]))
    return interior


def circumcircle_meets_segment(p, t, inputs, input_segs):
    (ax, ay), (bx, by), (cx, cy) = p[t[0]], p[t[1]], p[t[2]]
    d = 2 * (ax * (by - cy) + bx * (cy - ay) + cx * (ay - by))
    ux = ((ax * ax + ay * ay) * (by - cy) + (bx * bx + by * by) * (cy - ay) + (cx * cx + cy * cy) * (ay - by)) / d
    uy = ((ax * ax + ay * ay) * (cx - bx) + (bx * bx + by * by) * (ax - cx) + (cx * cx + cy * cy) * (bx - ax)) / d
    r = math.hypot(ax - ux, ay - uy)
    for s, e in input_segs:
        (sx, sy), (ex, ey) = inputs[s], inputs[e]
        dx, dy = ex - sx, ey - sy
        k = max(0.0, min(1.0, ((ux - sx) * dx + (uy - sy) * dy) / (dx * dx + dy * dy)))
        if math.hypot(sx + k * dx - ux, sy + k * dy - uy) <= r * (1 + 1e-9):
            return True
    return False


def check_interior(deltri, inp, algorithm, strategy, q, work):
    inputs, input_segs = require_eligible(inp)
    switches = ['-pq' + q, '--algorithm=' + algorithm, '--interior-bound=' + strategy]
    base = run(deltri, inp, switches, work)
    pts, tris, segs = read_mesh(base)
    interior = segment_interior(pts, segs, inputs, input_segs)
    q = float(q)
    faults, away, near, worst_away, worst_near = [], 0, 0, 180.0, 180.0
    for t in tris:
        m = min_angle(pts, t)
        touches = any(v in interior for v in t)
        if strategy == '1':
            bound = q if touches else max(q, 30.0)
        else:
            bound = q if m >= 30.0 - TOLERANCE or circumcircle_meets_segment(pts, t, inputs, input_segs) else 30.0
        if touches:
            near, worst_near = near + 1, min(worst_near, m)
        else:
            away, worst_away = away + 1, min(worst_away, m)
        if m < bound - TOLERANCE and len(faults) < 10:
            faults.append('triangle %s: smallest angle %.6f < %g (%s a segment interior)' % (t, m, bound, 'touches' if touches else 'away from'))
    report(faults, '%s %s: %d triangles; %d with no vertex in a segment interior (smallest angle %.4f), %d with one (%.4f)'
           % (inp, ' '.join(switches), len(tris), away, worst_away, near, worst_near))


def check_fewer(deltri, inp, q, work):
    require_eligible(inp)
    counts = {}
    faults = []
    for algorithm in ('ruppert', 'chew'):
        base = run(deltri, inp, ['-pq' + q, '--algorithm=' + algorithm], os.path.join(work, algorithm))
        pts, tris, segs = read_mesh(base)
        counts[algorithm] = len(tris)
        constrained = {frozenset(s) for s in segs} if algorithm == 'chew' else set()
        faults += ['%s: %s' % (algorithm, f) for f in delaunay_faults(pts, tris, constrained)[:5]]
        worst = min(min_angle(pts, t) for t in tris)
        if worst < float(q) - TOLERANCE:
            faults.append('%s: smallest angle %.6f < %s' % (algorithm, worst, q))
    if counts['chew'] >= counts['ruppert']:
        faults.append('Chew made %d triangles, not fewer than Ruppert\'s %d' % (counts['chew'], counts['ruppert']))
    report(faults, '%s -pq%s: Chew %d triangles, Ruppert %d (ratio %.3f)'
           % (inp, q, counts['chew'], counts['ruppert'], counts['chew'] / counts['ruppert']))


REFUSED = [
    (['-pDq', '--algorithm=chew'], 'constrained Delaunay meshes only'),
    (['-pq', '--interior-bound=1'], "Ruppert's or Chew's algorithm"),
    (['-p', '--algorithm=ruppert', '--interior-bound=2'], 'give -q'),
    (['-pq', '--algorithm=chew', '--decline-cluster-splits'], 'belongs to the Terminator'),
    (['-pq', '--algorithm=lawson'], 'terminator, ruppert or chew'),
    (['-pq', '--algorithm=ruppert', '--interior-bound=3'], 'give 1 or 2'),
]


def check_refusals(deltri, inp, work):
    faults = []
    shutil.copy(inp, work)
    name = os.path.basename(inp)
    for switches, expect in REFUSED:
        r = subprocess.run([deltri] + switches + [name], cwd=work, capture_output=True, text=True, timeout=60)
        lines = r.stderr.strip().split('\n')
        written = [f for f in os.listdir(work) if f != name]
        if r.returncode != 2 or len(lines) != 1 or expect not in lines[0] or written:
            faults.append('%s: exit %d, stderr %r, files %s' % (' '.join(switches), r.returncode, r.stderr, written))
    report(faults, '%d combinations refused with exit 2 and one line' % len(REFUSED))


def check_conformity(deltri, inp, work):
    switches = ['-pDq20.7', '--algorithm=ruppert']
    base = run(deltri, inp, switches, work)
    pts, tris, _ = read_mesh(base)
    faults = delaunay_faults(pts, tris, set())
    bad = sum(' not Delaunay: ' in f for f in faults)
    faults = [f for f in faults if ' not Delaunay: ' not in f]
    d = os.path.join(work, 'strict')
    os.makedirs(d)
    shutil.copy(inp, d)
    r = subprocess.run([deltri] + switches + ['--strict', '-Q', os.path.basename(inp)], cwd=d, capture_output=True,
                       text=True, timeout=900)
    warned = [line for line in r.stderr.splitlines() if 'not Delaunay' in line]
    expected = '%d subsegment%s not Delaunay' % (bad, ' is' if bad == 1 else 's are')
    if bad > 0 and not any(expected in line for line in warned):
        faults.append('%d edges not Delaunay, but no warning "%s": %s' % (bad, expected, warned))
    if bad == 0 and warned:
        faults.append('truly Delaunay, yet warned: %s' % warned)
    if bad > 0 and r.returncode != 3:
        faults.append('%d edges not Delaunay, yet --strict exits %d, not 3' % (bad, r.returncode))
    report(faults, '%s ruppert -pDq20.7: %d triangles, %d edges not Delaunay, warned of exactly; --strict exit %d'
           % (inp, len(tris), bad, r.returncode))


def write_poly(path, pts, segs):
    with open(path, 'w') as f:
        f.write('%d 2 0 0\n' % len(pts) + ''.join('%d %r %r\n' % (i + 1, x, y) for i, (x, y) in enumerate(pts)))
        f.write('%d 0\n' % len(segs) + ''.join('%d %d %d\n' % (i + 1, a, b) for i, (a, b) in enumerate(segs)))
        f.write('0\n')


def wedge_poly(path, degrees, second=0.9):
    a = math.radians(degrees)
    pts = [(-1.0, -1.0), (2.0, -1.0), (2.0, 1.0), (-1.0, 1.0), (0.0, 0.0), (1.0, 0.0),
           (second * math.cos(a), second * math.sin(a))]
    segs = [(1, 2), (2, 3), (3, 4), (4, 1), (5, 6), (5, 7)]
    write_poly(path, pts, segs)


def limit_memory():
    # AddressSanitizer reserves terabytes of address space for its shadow memory and cannot run
    # under the limit; the sanitizer build sets DELTRI_NO_ADDRESS_LIMIT (the 300 s guard stays).
    if not os.environ.get('DELTRI_NO_ADDRESS_LIMIT'):
        resource.setrlimit(resource.RLIMIT_AS, (4 << 30, 4 << 30))


def check_sure_fire(deltri, degrees, switches, work):
    inp = os.path.join(work, 'wedge.poly')
    wedge_poly(inp, float(degrees))
    try:
        r = subprocess.run([deltri] + switches + ['-Q', '--json=wedge.json', 'wedge.poly'], cwd=work, capture_output=True,
                           text=True, timeout=300, preexec_fn=limit_memory)
    except subprocess.TimeoutExpired:
        raise SystemExit('FAIL: %s degrees %s: no end within 300 s (the ping-pong was not stopped)' % (degrees, switches))
    if r.returncode != 0:
        raise SystemExit('FAIL: %s degrees %s: exit %d: %s' % (degrees, switches, r.returncode, r.stderr.strip()[-300:]))
    q = json.load(open(os.path.join(work, 'wedge.json')))['quality']
    faults = []
    why = ' | '.join(q.get('why_missed', []))
    if 'sure-fire' not in why or not q.get('sure_fire_refusals', 0) > 0:
        faults.append('the report does not name the sure-fire rule: %r, refusals %r' % (why, q.get('sure_fire_refusals')))
    if 'cap' in why:
        faults.append('the Steiner cap stopped refinement: %r' % why)
    pts, tris, segs = read_mesh(os.path.join(work, 'wedge.1'))
    faults += delaunay_faults(pts, tris, {frozenset(s) for s in segs})[:5]
    exact = {k: (Fraction(x), Fraction(y)) for k, (x, y) in pts.items()}
    area = sum(orient(exact[a], exact[b], exact[c]) for a, b, c in tris) / 2
    if area != 6:
        faults.append('the triangles cover %s, not the box\'s 6' % float(area))
    report(faults, '%s degrees %s: %d triangles, %d sure-fire refusals, constrained Delaunay, covers the box'
           % (degrees, ' '.join(switches), len(tris), q.get('sure_fire_refusals', 0)))


def crossing_poly(path, degrees):
    """The sure_fire box with two segments of length about 1 that cross at (0.5, 0) at DEG degrees, their
    ends paired at x = 0 and x = 1: each thin wedge at the crossing is closed at its far end by two input
    vertices, a gap of tan(DEG / 2) apart."""
    h = 0.5 * math.tan(math.radians(degrees) / 2)
    pts = [(-1.0, -1.0), (2.0, -1.0), (2.0, 1.0), (-1.0, 1.0), (0.0, -h), (1.0, h), (0.0, h), (1.0, -h)]
    segs = [(1, 2), (2, 3), (3, 4), (4, 1), (5, 6), (7, 8)]
    write_poly(path, pts, segs)


def check_chew_wedge(deltri, degrees, q, second, work):
    inp = os.path.join(work, 'wedge.poly')
    wedge_poly(inp, float(degrees), float(second))
    compare_chew_ruppert(deltri, inp, '%s degrees, lengths 1 and %s, -pq%s' % (degrees, second, q), q, work)


def check_chew_crossing(deltri, degrees, q, work):
    inp = os.path.join(work, 'crossing.poly')
    crossing_poly(inp, float(degrees))
    compare_chew_ruppert(deltri, inp, 'crossing at %s degrees -pq%s' % (degrees, q), q, work)


def compare_chew_ruppert(deltri, inp, label, q, work):
    """Chew at -pqQ within 4 times Ruppert's triangles and no edge under 1/4 of Ruppert's shortest; both
    meshes constrained Delaunay (exact) and covering the box. A run past the first bound is not checked
    exactly (the runaway meshes have up to 700,000 triangles)."""
    meshes, counts, shortest, faults = {}, {}, {}, []
    for algorithm in ('ruppert', 'chew'):
        base = run(deltri, inp, ['-pq' + q, '--algorithm=' + algorithm], os.path.join(work, algorithm))
        pts, tris, segs = read_mesh(base)
        meshes[algorithm] = (pts, tris, segs)
        counts[algorithm] = len(tris)
        shortest[algorithm] = min(math.dist(pts[t[i]], pts[t[(i + 1) % 3]]) for t in tris for i in range(3))
    if counts['chew'] > 4 * counts['ruppert']:
        faults.append('Chew made %d triangles, more than 4 times Ruppert\'s %d' % (counts['chew'], counts['ruppert']))
    if shortest['chew'] < shortest['ruppert'] / 4:
        faults.append('Chew\'s shortest edge %.3g is under a quarter of Ruppert\'s %.3g' % (shortest['chew'], shortest['ruppert']))
    for algorithm, (pts, tris, segs) in meshes.items():
        if faults:
            break
        faults += ['%s: %s' % (algorithm, f) for f in delaunay_faults(pts, tris, {frozenset(s) for s in segs})[:5]]
        exact = {k: (Fraction(x), Fraction(y)) for k, (x, y) in pts.items()}
        if sum(orient(exact[a], exact[b], exact[c]) for a, b, c in tris) != 12:  # twice the box's 6
            faults.append('%s: the triangles do not cover the box' % algorithm)
    report(faults, '%s: Chew %d triangles, Ruppert %d (ratio %.2f); shortest edges %.3g and %.3g'
           % (label, counts['chew'], counts['ruppert'], counts['chew'] / counts['ruppert'], shortest['chew'],
              shortest['ruppert']))


def check_near_limit(deltri, inp, algorithm, work):
    switches = ['--algorithm=' + algorithm]
    pts, tris, _ = read_mesh(run(deltri, inp, ['-pq30'] + switches, work))
    low_count, low_worst = len(tris), min(min_angle(pts, t) for t in tris)
    pts, tris, _ = read_mesh(run(deltri, inp, ['-pq34'] + switches, work))
    worst = min(min_angle(pts, t) for t in tris)
    misses = sum(1 for t in tris if min_angle(pts, t) < 34.0 - TOLERANCE)
    faults = []
    if worst < low_worst - TOLERANCE:
        faults.append('-pq34: smallest angle %.4f below the -pq30 mesh\'s %.4f' % (worst, low_worst))
    if len(tris) > 10 * low_count:
        faults.append('-pq34: %d triangles, more than 10 times the -pq30 mesh\'s %d' % (len(tris), low_count))
    d = os.path.join(work, 'loud')
    os.makedirs(d)
    shutil.copy(inp, d)
    r = subprocess.run([deltri, '-pq34'] + switches + [os.path.basename(inp)], cwd=d, capture_output=True,
                       text=True, timeout=900)
    warned = re.search(r'warning: .*?(\d+) triangles? miss', r.stderr)
    if misses and (warned is None or int(warned.group(1)) != misses):
        faults.append('-pq34: %d triangles under 34 degrees, but the warning says %s' %
                      (misses, warned.group(0) if warned else 'nothing'))
    report(faults, '%s %s -pq34: %d triangles (-pq30: %d), smallest angle %.4f (-pq30: %.4f), %d under 34, warned' %
           (inp, algorithm, len(tris), low_count, worst, low_worst, misses))


def report(faults, summary):
    for f in faults[:10]:
        print('FAIL:', f)
    if faults:
        raise SystemExit(1)
    print('ok:', summary)


def main(argv):
    mode = argv[1]
    if mode == 'eligible':
        for inp in argv[2:]:
            try:
                pts, segs = read_poly(inp)
                if segs and smallest_input_angle(pts, segs) >= 60.0 - TOLERANCE:
                    print(inp, flush=True)
            except (ValueError, IndexError, KeyError, OSError):
                continue  # not a file this reader takes (the tool is for choosing inputs)
        return 0
    work = tempfile.mkdtemp()
    try:
        if mode == 'ruppert':
            check_ruppert(argv[2], argv[3], work)
        elif mode == 'interior':
            check_interior(argv[2], argv[3], argv[4], argv[5], argv[6], work)
        elif mode == 'fewer':
            check_fewer(argv[2], argv[3], argv[4], work)
        elif mode == 'refusals':
            check_refusals(argv[2], argv[3], work)
        elif mode == 'conformity':
            check_conformity(argv[2], argv[3], work)
        elif mode == 'chew_wedge':
            check_chew_wedge(argv[2], argv[3], argv[4], argv[5] if len(argv) > 5 else '0.9', work)
        elif mode == 'chew_crossing':
            check_chew_crossing(argv[2], argv[3], argv[4], work)
        elif mode == 'near_limit':
            check_near_limit(argv[2], argv[3], argv[4], work)
        elif mode == 'sure_fire':
            check_sure_fire(argv[2], argv[3], argv[4:], work)
        else:
            raise SystemExit('unknown mode ' + mode)
    finally:
        shutil.rmtree(work)
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
