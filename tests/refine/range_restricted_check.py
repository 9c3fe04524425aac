#!/usr/bin/python3
"""Independent check of range-restricted segment splitting (Shewchuk 2001, Sec. 7.3) on deltri's
output files, computed from the input .poly and the output .node/.poly/.ele only.

  range_restricted_check.py INPUT.poly OUTBASE TOP [--min-angle DEG]

TOP is the top of the legal mantissa range (sqrt 3 with lenses, sqrt 2 with -D). The unit of the
ladder is the coordinate unit (the one the concentric shells measure their power-of-two radii in).
For every input segment, its output subsegments are found geometrically (both ends on it) and:
  - their lengths must add up to the segment's (it is covered);
  - at most one of them may have an illegal length c 2^x, c in [TOP, 2): the piece never split
    again (a whole segment, or the middle left between the shell splits at its ends);
  - merging neighbours of equal length (undoing bisections) must leave at most 4 pieces: at most
    three unbalanced splits per input segment (two shell splits, one range-restricted split).
With --min-angle, every triangle's angles must lie in [DEG, 180 - 2 DEG].
Prints one summary line; exit 1 on any failure (the first few are printed).
"""
import math
import sys

SLACK = 1e-7


def records(path):
    for line in open(path):
        fields = line.split('#')[0].split()
        if fields:
            yield fields


def read_points(lines, count):
    return {int(f[0]): (float(f[1]), float(f[2])) for f in (next(lines) for _ in range(count))}


def read_poly(path):
    lines = records(path)
    n = int(next(lines)[0])
    points = read_points(lines, n) if n else None
    if points is None:
        node = records(path[:-5] + '.node')
        points = read_points(node, int(next(node)[0]))
    m = int(next(lines)[0])
    segments = [(int(f[1]), int(f[2])) for f in (next(lines) for _ in range(m))]
    return points, segments


def mantissa(length):
    fraction, exponent = math.frexp(length)
    return 2.0 * fraction


def legal(length, top):
    c = mantissa(length)
    return c < top * (1 + SLACK) or c > 2 * (1 - SLACK)


def on_segment(p, a, b):
    ax, ay = b[0] - a[0], b[1] - a[1]
    length2 = ax * ax + ay * ay
    px, py = p[0] - a[0], p[1] - a[1]
    t = (px * ax + py * ay) / length2
    cross = abs(px * ay - py * ax) / math.sqrt(length2)
    return -1e-9 <= t <= 1 + 1e-9 and cross <= 1e-9 * math.sqrt(length2), t


def pieces_of(a, b, out_points, out_segments):
    found = []
    for u, v in out_segments:
        on_u, tu = on_segment(out_points[u], a, b)
        on_v, tv = on_segment(out_points[v], a, b)
        if on_u and on_v:
            found.append((min(tu, tv), math.dist(out_points[u], out_points[v])))
    return [length for _, length in sorted(found)]


def unbalanced_splits(lengths):
    """The splits left once neighbours of equal length are merged back (bisections undone)."""
    pieces = list(lengths)
    merged = True
    while merged:
        merged = False
        for i in range(len(pieces) - 1):
            if abs(pieces[i] - pieces[i + 1]) <= 1e-9 * pieces[i]:
                pieces[i:i + 2] = [pieces[i] + pieces[i + 1]]
                merged = True
                break
    return len(pieces) - 1


def angles(p, q, r):
    def angle(o, s, t):
        a = math.atan2(s[1] - o[1], s[0] - o[0]) - math.atan2(t[1] - o[1], t[0] - o[0])
        a = abs(math.degrees(a)) % 360
        return min(a, 360 - a)
    return angle(p, q, r), angle(q, r, p), angle(r, p, q)


def main():
    in_path, base, top = sys.argv[1], sys.argv[2], float(sys.argv[3])
    min_angle = float(sys.argv[5]) if len(sys.argv) > 5 and sys.argv[4] == '--min-angle' else None
    points, segments = read_poly(in_path)
    node = records(base + '.node')
    out_points = read_points(node, int(next(node)[0]))
    _, out_segments = read_poly(base + '.poly')
    failures = []
    stats = {'segments': 0, 'split': 0, 'illegal_left': 0, 'most_unbalanced': 0, 'subsegments': 0}
    for a, b in segments:
        if a == b:
            continue
        pa, pb = points[a], points[b]
        lengths = pieces_of(pa, pb, out_points, out_segments)
        total = math.dist(pa, pb)
        stats['segments'] += 1
        stats['subsegments'] += len(lengths)
        if abs(sum(lengths) - total) > 1e-9 * total:
            failures.append(f'segment {a}-{b}: subsegments cover {sum(lengths)} of {total}')
            continue
        if len(lengths) > 1:
            stats['split'] += 1
        illegal = [x for x in lengths if not legal(x, top)]
        stats['illegal_left'] += len(illegal)
        if len(illegal) > 1:
            failures.append(f'segment {a}-{b}: {len(illegal)} subsegments of illegal length, e.g. {illegal[0]!r}')
        unbalanced = unbalanced_splits(lengths)
        stats['most_unbalanced'] = max(stats['most_unbalanced'], unbalanced)
        if unbalanced > 3:
            failures.append(f'segment {a}-{b}: {unbalanced} unbalanced splits')
    smallest, largest = 180.0, 0.0
    if min_angle is not None:
        ele = records(base + '.ele')
        count = int(next(ele)[0])
        for _ in range(count):
            f = next(ele)
            tri = angles(*(out_points[int(i)] for i in f[1:4]))
            smallest, largest = min(smallest, min(tri)), max(largest, max(tri))
        if smallest < min_angle - 1e-9 or largest > 180 - 2 * min_angle + 1e-9:
            failures.append(f'angles {smallest:.4f}..{largest:.4f} outside [{min_angle}, {180 - 2 * min_angle}]')
    print(f'{in_path}: {stats["segments"]} segments, {stats["split"]} split, {stats["subsegments"]} subsegments, '
          f'{stats["illegal_left"]} illegal left, at most {stats["most_unbalanced"]} unbalanced splits, '
          f'angles {smallest:.3f}..{largest:.3f}: {"FAIL" if failures else "ok"}')
    for f in failures[:5]:
        print('  ' + f)
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())
