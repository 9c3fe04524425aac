#!/usr/bin/env python3
"""--range-restricted (Shewchuk 2001, Sec. 7.3) on PSLGs whose input angles are all 60 degrees or
more, checked from the output files by range_restricted_check.py (beside this file):

    range_restricted.py DELTRI [DATA_DIR]

For each input (generated here, with side lengths chosen illegal, plus DATA_DIR/box.poly) and each
switch set (-pq30, -pq30 with an area bound that forces many segment splits, -pDq30 with the
diametral circles' range [1, sqrt 2)): deltri must end with status 0 (termination), every angle
must lie in [30, 120], every input segment's subsegments must be legal but for one piece never
split again, with at most three unbalanced splits per input segment; a second run must write the
same bytes. The same check on the runs without --range-restricted must fail somewhere (the
default splits illegal subsegments at midpoints), or this test could not fail.
"""
import hashlib, math, os, shutil, subprocess, sys, tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
CHECK = os.path.join(HERE, 'range_restricted_check.py')
SQRT3, SQRT2 = math.sqrt(3.0), math.sqrt(2.0)


def write_poly(path, loops, holes):
    points, segments = [], []
    for loop in loops:
        first = len(points)
        points.extend(loop)
        segments.extend((first + i, first + (i + 1) % len(loop)) for i in range(len(loop)))
    with open(path, 'w') as f:
        f.write(f'{len(points)} 2 0 0\n')
        f.writelines(f'{i + 1} {x!r} {y!r}\n' for i, (x, y) in enumerate(points))
        f.write(f'{len(segments)} 0\n')
        f.writelines(f'{i + 1} {a + 1} {b + 1}\n' for i, (a, b) in enumerate(segments))
        f.write(f'{len(holes)}\n')
        f.writelines(f'{i + 1} {x!r} {y!r}\n' for i, (x, y) in enumerate(holes))


def regular(n, side, cx=0.0, cy=0.0, turn=0.0):
    r = side / (2 * math.sin(math.pi / n))
    return [(cx + r * math.cos(turn + 2 * math.pi * k / n), cy + r * math.sin(turn + 2 * math.pi * k / n))
            for k in range(n)]


def inputs(work, data_dir):
    """Side lengths 1.8, 3.5, 0.45, 1.9, 0.47, 1.75: mantissas in [sqrt 3, 2), illegal in both ranges."""
    made = {
        'rect_hole': ([[(0, 0), (1.8, 0), (1.8, 3.5), (0, 3.5)],
                       [(0.6, 1.2), (1.05, 1.2), (1.05, 1.65), (0.6, 1.65)]], [(0.8, 1.4)]),
        'hexagon': ([regular(6, 1.9), regular(6, 0.47, 0.3, 0.1)], [(0.3, 0.1)]),
        'triangle': ([regular(3, 1.75)], []),
        # 11 points on a circle at uneven spacing: interior angles between 130 and 155 degrees.
        'circle': ([[(2.3 * math.cos(a), 2.3 * math.sin(a))
                     for a in (2 * math.pi * (k + 0.3 * math.sin(3.7 * k)) / 11 for k in range(11))]], []),
    }
    paths = []
    for name, (loops, holes) in made.items():
        paths.append(os.path.join(work, name + '.poly'))
        write_poly(paths[-1], loops, holes)
    box = os.path.join(data_dir, 'box.poly')
    if os.path.exists(box):
        paths.append(shutil.copy(box, work))
    return paths


def run(deltri, path, switches):
    """Runs deltri in the input's directory; returns (status, digest of the outputs)."""
    base = path[:-5]
    for ext in ('node', 'ele', 'poly'):
        if os.path.exists(f'{base}.1.{ext}'):
            os.remove(f'{base}.1.{ext}')
    status = subprocess.run([deltri] + switches + [os.path.basename(path)], cwd=os.path.dirname(path),
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, timeout=300).returncode
    digest = hashlib.sha256()
    for ext in ('node', 'ele', 'poly'):
        if os.path.exists(f'{base}.1.{ext}'):
            digest.update(open(f'{base}.1.{ext}', 'rb').read())
    return status, digest.hexdigest()


def check(path, top):
    out = subprocess.run(['/usr/bin/python3', CHECK, path, path[:-5] + '.1', repr(top), '--min-angle', '30'],
                         capture_output=True, text=True)
    return out.returncode, out.stdout.strip()


def main():
    deltri = os.path.abspath(sys.argv[1])
    data_dir = sys.argv[2] if len(sys.argv) > 2 else os.path.join(HERE, '..', '..', 'data')
    failures, default_caught = 0, 0
    with tempfile.TemporaryDirectory() as work:
        for path in inputs(work, data_dir):
            for switches, top in ((['-pq30Q'], SQRT3), (['-pq30a0.01Q'], SQRT3), (['-pDq30a0.01Q'], SQRT2)):
                status, digest = run(deltri, path, switches + ['--range-restricted'])
                code, line = check(path, top) if status == 0 else (1, f'{path}: deltri exit status {status}')
                again = run(deltri, path, switches + ['--range-restricted'])
                if again != (status, digest):
                    code, line = 1, line + ' (a second run wrote different bytes)'
                print(' '.join(switches), '--range-restricted:', line)
                failures += code != 0
                if run(deltri, path, switches)[0] == 0 and check(path, top)[0] != 0:
                    default_caught += 1
    print(f'the same check failed on {default_caught} of the runs without --range-restricted')
    if default_caught == 0:
        print('FAIL: the check never fails without --range-restricted: it cannot tell the policy apart')
        failures += 1
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())
