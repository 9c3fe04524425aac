#!/usr/bin/env python3
"""--corner-lopping (Shewchuk 2001, Sec. 6.1) checked from the output files, and compared with the
Terminator (deltri's default):

    corner_lopping.py DELTRI DATA_DIR [--table]

Inputs: a 20-degree wedge, a five-pointed star (36-degree tips), a fan of segments 14 degrees apart,
a polyline hanging in a square that turns back by 0.89 degrees (an excerpt of water.poly: the
domain on both sides of that vertex; generated here) and DATA_DIR's guitar.poly (45 degrees) and
issue-142-double-hanging-edge.poly (1.16 degrees). For each at -pq20 and -pq30 with --corner-lopping:
  - deltri ends with status 0, and a second run writes the same bytes;
  - the output is a mesh of the original PSLG: every triangle counter-clockwise, the triangles'
    total area that of the Terminator's mesh of the same input, every input segment covered by
    output segments, and every output segment on an input segment (shield edges and spokes are
    internal, not segments);
  - on the generated inputs, each apex deltri lops (a sector under 60 degrees inside the domain, none
    of them next to a wider sector inside: computed here) is lopped: the first output vertex along
    each of its segments lies at lfs/3 (lfs computed here) and the triangles at the apex lie within
    that circle (its fan);
  - at -pq20 (B = sqrt 2: the bound the paper proves for Ruppert's algorithm on X', whose angles
    are all 60 degrees or more), every triangle that has no input vertex of an input angle under
    60 degrees as a corner (the fans in the lopped corners are the paper's exemption) has no angle
    under 20; on the hanging polyline, whose apex is left to refinement, every triangle with an
    angle under 20 lies inside a small input angle at its apex or has its shortest edge across the
    two segments of one (the shells), which failed before such apices were left alone (6 thin
    triangles at the apex in its 359-degree sector). At 30 degrees the paper proves nothing for X'
    without range-restricted splitting; there the Terminator's equal-distance exemption at junctions of 60-90 degrees leaves a few
    triangles (the fan at -pq30: one of 26.3 degrees), so -pq30 is checked for validity only.
With --table, prints the comparison of docs/refinement.md (triangles, angles under q, shortest edge
over the shortest input segment) for both modes.
"""
import math, os, shutil, subprocess, sys, tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from range_restricted import write_poly  # noqa: E402
from range_restricted_check import read_poly, records, read_points, on_segment, pieces_of  # noqa: E402


def generated(work):
    star = []
    for k in range(10):
        r = 2.0 if k % 2 == 0 else 2.0 * math.sin(math.radians(18)) / math.sin(math.radians(126))
        a = math.radians(90 + 36 * k)
        star.append((r * math.cos(a), r * math.sin(a)))
    OUTER['star.poly'] = star
    made = {'wedge': ([[(0, 0), (10, 0), (9, 3.2)]], []), 'star': ([star], [])}
    paths = []
    for name, (loops, holes) in made.items():
        paths.append(os.path.join(work, name + '.poly'))
        write_poly(paths[-1], loops, holes)
    # The fan: a square with five segments from one corner to points on the far sides, 14 degrees apart
    # (no angle of exactly 60 degrees, where the shells' equal-distance exemption applies).
    fan = os.path.join(work, 'fan.poly')
    rays = [(4.0, 4.0 * math.tan(math.radians(a))) if a <= 45 else (4.0 / math.tan(math.radians(a)), 4.0)
            for a in (14, 28, 42, 56, 70)]
    pts = [(0, 0), (4, 0), rays[0], rays[1], rays[2], (4, 4), rays[3], rays[4], (0, 4)]
    with open(fan, 'w') as f:
        f.write(f'{len(pts)} 2 0 0\n' + ''.join(f'{i + 1} {x!r} {y!r}\n' for i, (x, y) in enumerate(pts)))
        segs = [(1, 2), (2, 3), (3, 4), (4, 5), (5, 6), (6, 7), (7, 8), (8, 9), (9, 1)] + [(1, k) for k in (3, 4, 5, 7, 8)]
        f.write(f'{len(segs)} 0\n' + ''.join(f'{i + 1} {a} {b}\n' for i, (a, b) in enumerate(segs)) + '0\n')
    # Hanging: a polyline in a square (the part of mapbox/earcut's water.poly within 45 of its vertex
    # (3622, 3995), moved to the origin) that turns back at the origin by 0.89 degrees: the domain lies
    # on both sides of the vertex, a small sector and a 359-degree one. Lopping both (the wide one's
    # arc cut into 60-degree pieces) let refinement split the wide sector's chords, leaving thin fan
    # triangles at the origin outside its small angle (6, down to 8 degrees, at -pq20).
    hanging = os.path.join(work, 'hanging.poly')
    pts = [(-27, 30), (-18, 30), (0, 0), (-11, 19), (-9, 27), (-29, 36), (-45, -45), (45, -45), (45, 45), (-45, 45)]
    with open(hanging, 'w') as f:
        f.write(f'{len(pts)} 2 0 0\n' + ''.join(f'{i + 1} {x!r} {y!r}\n' for i, (x, y) in enumerate(pts)))
        segs = [(1, 2), (2, 3), (3, 4), (4, 5), (5, 6), (7, 8), (8, 9), (9, 10), (10, 7)]
        f.write(f'{len(segs)} 0\n' + ''.join(f'{i + 1} {a} {b}\n' for i, (a, b) in enumerate(segs)) + '0\n')
    return paths + [fan, hanging]


# The outer boundary of each generated input (no holes): which sectors at a vertex lie inside.
OUTER = {'wedge.poly': [(0, 0), (10, 0), (9, 3.2)], 'fan.poly': [(0, 0), (4, 0), (4, 4), (0, 4)],
         'hanging.poly': [(-45, -45), (45, -45), (45, 45), (-45, 45)]}


def inside_polygon(p, loop):
    crossings = False
    for (ax, ay), (bx, by) in zip(loop, loop[1:] + loop[:1]):
        if (ay > p[1]) != (by > p[1]) and p[0] < ax + (p[1] - ay) * (bx - ax) / (by - ay):
            crossings = not crossings
    return crossings


def angles(p, q, r):
    def at(o, s, t):
        d = abs(math.atan2(s[1] - o[1], s[0] - o[0]) - math.atan2(t[1] - o[1], t[0] - o[0]))
        d = math.degrees(d) % 360
        return min(d, 360 - d)
    return at(p, q, r), at(q, r, p), at(r, p, q)


def segment_neighbours(segments):
    """For each vertex, the other ends of the (non-degenerate) segments at it."""
    around = {}
    for a, b in segments:
        if a != b:
            around.setdefault(a, []).append(b)
            around.setdefault(b, []).append(a)
    return around


def small_angle_apices(points, segments):
    """Input vertices between two segments at less than 60 degrees (all sectors, inside or not)."""
    around = segment_neighbours(segments)
    apices = set()
    for v, ws in around.items():
        d = sorted(math.atan2(points[w][1] - points[v][1], points[w][0] - points[v][0]) for w in ws)
        if len(d) > 1 and any((d[(k + 1) % len(d)] - d[k]) % (2 * math.pi) < math.pi / 3 * (1 - 1e-9) for k in range(len(d))):
            apices.add(points[v])
    return apices


def lopped_apices(points, segments, outer):
    """The apices deltri lops: a sector under 60 degrees inside the domain, and no such sector next to
    a wider one inside (an angle at a vertex the domain lies on both sides of is left to refinement)."""
    around = segment_neighbours(segments)
    apices = set()
    for v, ws in around.items():
        if len(ws) < 2:
            continue
        o = points[v]
        d = sorted(math.atan2(points[w][1] - o[1], points[w][0] - o[0]) for w in ws)
        n = len(d)
        width = [(d[(k + 1) % n] - d[k]) % (2 * math.pi) or 2 * math.pi for k in range(n)]
        mid = [d[k] + width[k] / 2 for k in range(n)]
        inside = [inside_polygon((o[0] + 1e-6 * math.cos(m), o[1] + 1e-6 * math.sin(m)), outer) for m in mid]
        small = [inside[k] and width[k] < math.pi / 3 * (1 - 1e-9) for k in range(n)]
        if any(small) and not any(small[k] and inside[j] and not small[j] for k in range(n) for j in ((k + 1) % n, k - 1)):
            apices.add(o)
    return apices


def in_small_sector(points, segments, tri, apex_points):
    """Whether triangle tri (three points) has a corner at an input vertex of apex_points with its other
    two corners inside one of that vertex's sectors under 60 degrees (an input angle's own triangles)."""
    for i in range(3):
        o = tri[i]
        if o not in apex_points:
            continue
        v = next(u for u, p in points.items() if p == o)
        d = sorted(math.atan2(points[w][1] - o[1], points[w][0] - o[0])
                   for a, b in segments if v in (a, b) and a != b for w in (b if a == v else a,))
        for k in range(len(d)):
            lo, width = d[k], (d[(k + 1) % len(d)] - d[k]) % (2 * math.pi)
            if width < math.pi / 3 and all((math.atan2(q[1] - o[1], q[0] - o[0]) - lo) % (2 * math.pi) <= width + 1e-12
                                           for q in (tri[(i + 1) % 3], tri[(i + 2) % 3])):
                return True
    return False


def across_small_angle(points, segments, tri):
    """Whether tri's shortest edge joins points on two input segments that meet at an angle under 60
    degrees (the concentric shells' triangles, which refinement leaves at an apex it does not lop)."""
    u, w = min(((tri[i], tri[(i + 1) % 3]) for i in range(3)), key=lambda e: math.dist(*e))
    for s1 in segments:
        for s2 in segments:
            shared = set(s1) & set(s2)
            if s1 == s2 or len(shared) != 1 or not on_segment(u, points[s1[0]], points[s1[1]])[0] \
                    or not on_segment(w, points[s2[0]], points[s2[1]])[0]:
                continue
            o = points[shared.pop()]
            p, q = (points[x] for x in (*s1, *s2) if points[x] != o)
            turn = abs(math.atan2(p[1] - o[1], p[0] - o[0]) - math.atan2(q[1] - o[1], q[0] - o[0])) % (2 * math.pi)
            if min(turn, 2 * math.pi - turn) < math.pi / 3:
                return True
    return False


def feature_size(v, points, segments):
    """lfs at input vertex v: the nearest other vertex or segment without v as an end."""
    p = points[v]
    def to_segment(a, b):
        dx, dy = b[0] - a[0], b[1] - a[1]
        t = max(0.0, min(1.0, ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / (dx * dx + dy * dy)))
        return math.dist(p, (a[0] + t * dx, a[1] + t * dy))
    return min([math.dist(p, w) for u, w in points.items() if u != v] +
               [to_segment(points[a], points[b]) for a, b in segments if v not in (a, b) and a != b])


def shield_problems(points, segments, out, tris, out_segments, outer):
    """At each apex lopped (lopped_apices), the first output vertex along each of its segments is at
    lfs/3, and every triangle at the apex lies within that circle."""
    problems = 0
    apex_points = lopped_apices(points, segments, outer)
    for v, p in points.items():
        if p not in apex_points:
            continue
        r = feature_size(v, points, segments) / 3
        ids = {i for i, q in out.items() if q == p}
        near = [math.dist(p, out[w]) for t in tris if ids & set(t) for w in t if w not in ids]
        problems += any(d > r * (1 + 1e-9) for d in near)
        for a, b in segments:
            if v in (a, b):
                other = points[b if a == v else a]
                first = min(math.dist(p, out[w]) for u, w in out_segments + [(y, x) for x, y in out_segments]
                            if u in ids and on_segment(out[w], p, other)[0])
                problems += abs(first - r) > 1e-9 * r
    return problems


def measure(path, base, q):
    points, segments = read_poly(path)
    node = records(base + '.node')
    out = read_points(node, int(next(node)[0]))
    ele = records(base + '.ele')
    tris = [tuple(int(i) for i in f[1:4]) for f in (next(ele) for _ in range(int(next(ele)[0])))]
    _, out_segments = read_poly(base + '.poly')
    apices = small_angle_apices(points, segments)
    m = {'triangles': len(tris), 'under_q': 0, 'bad_outside': 0, 'area': 0.0, 'clockwise': 0,
         'uncovered': 0, 'stray_segments': 0, 'shields': 0, 'bad_outside_small_sectors': 0}
    shortest = math.inf
    for t in tris:
        p, r, s = (out[i] for i in t)
        area = 0.5 * ((r[0] - p[0]) * (s[1] - p[1]) - (r[1] - p[1]) * (s[0] - p[0]))
        m['area'] += area
        m['clockwise'] += area <= 0
        a = angles(p, r, s)
        m['under_q'] += sum(x < q for x in a)
        if min(a) < q - 1e-9 and not any(v in apices for v in (p, r, s)):
            m['bad_outside'] += 1
        if os.path.basename(path) == 'hanging.poly' and min(a) < q - 1e-9 and \
                not in_small_sector(points, segments, (p, r, s), apices) and not across_small_angle(points, segments, (p, r, s)):
            m['bad_outside_small_sectors'] += 1
        shortest = min(shortest, math.dist(p, r), math.dist(r, s), math.dist(s, p))
    for a, b in segments:
        if a != b:
            total = math.dist(points[a], points[b])
            m['uncovered'] += abs(sum(pieces_of(points[a], points[b], out, out_segments)) - total) > 1e-9 * total
    for u, v in out_segments:
        m['stray_segments'] += not any(on_segment(out[u], points[a], points[b])[0] and
                                       on_segment(out[v], points[a], points[b])[0] for a, b in segments if a != b)
    if os.path.basename(path) in OUTER:
        m['shields'] = shield_problems(points, segments, out, tris, out_segments, OUTER[os.path.basename(path)])
    shortest_input = min(math.dist(points[a], points[b]) for a, b in segments if a != b)
    m['shortest'] = shortest / shortest_input
    return m


def run(deltri, path, switches):
    base = path[:-5] + '.1'
    for ext in ('node', 'ele', 'poly'):
        if os.path.exists(f'{base}.{ext}'):
            os.remove(f'{base}.{ext}')
    status = subprocess.run([deltri] + switches + [os.path.basename(path)], cwd=os.path.dirname(path),
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, timeout=300).returncode
    data = b''.join(open(f'{base}.{ext}', 'rb').read() for ext in ('node', 'ele', 'poly') if os.path.exists(f'{base}.{ext}'))
    return status, data


def main():
    deltri, data_dir = os.path.abspath(sys.argv[1]), sys.argv[2]
    table = '--table' in sys.argv
    failures = 0
    with tempfile.TemporaryDirectory() as work:
        paths = generated(work)
        for name in ('guitar.poly', 'issue-142-double-hanging-edge.poly'):
            paths.append(shutil.copy(os.path.join(data_dir, name), work))
        if table:
            print('| input | q | Terminator: triangles, angles < q, shortest edge | corner-lopping: triangles, angles < q, shortest edge |')
            print('|---|---|---|---|')
        for path in paths:
            for q in (20, 30):
                status, _ = run(deltri, path, [f'-pq{q}Q'])
                base_m = measure(path, path[:-5] + '.1', q) if status == 0 else None
                status, data = run(deltri, path, [f'-pq{q}Q', '--corner-lopping'])
                problems = [] if status == 0 else [f'exit status {status}']
                if status == 0:
                    m = measure(path, path[:-5] + '.1', q)
                    if run(deltri, path, [f'-pq{q}Q', '--corner-lopping']) != (status, data):
                        problems.append('a second run wrote different bytes')
                    for key in ('clockwise', 'uncovered', 'stray_segments', 'shields', 'bad_outside_small_sectors') + \
                            (('bad_outside',) if os.path.basename(path) != 'hanging.poly' else ()):
                        if m[key] and (not key.startswith('bad_outside') or q <= 20):
                            problems.append(f'{key} {m[key]}')
                    if base_m and abs(m['area'] - base_m['area']) > 1e-9 * base_m['area']:
                        problems.append(f'area {m["area"]!r} against {base_m["area"]!r}')
                name = os.path.basename(path)
                if table and base_m and not problems:
                    print(f'| {name} | {q} | {base_m["triangles"]}, {base_m["under_q"]}, {base_m["shortest"]:.3g} '
                          f'| {m["triangles"]}, {m["under_q"]}, {m["shortest"]:.3g} |')
                elif not table:
                    print(f'{name} -pq{q} --corner-lopping: {"; ".join(problems) or "ok"}'
                          + (f' ({m["triangles"]} triangles, {m["under_q"]} angles under {q})' if status == 0 else ''))
                failures += bool(problems)
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())
