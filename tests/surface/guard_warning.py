"""The surface guard's warning counts what it says (issue 25, the brief's "loud, counted statement").

Runs deltri -pq30a20S5000 on the pyNastran gear, whose rounds spend that budget before the facets
agree, so that the facets are meshed once more with their segments kept (the pass the round cap
ends in too), and checks that the warning's counts of triangles below the -q angle and above the -a area equal the
counts recomputed here from the written .node/.ele, and that -C passes (the -YY pass conforms).
usage: guard_warning.py DELTRI SOURCE_DIR
"""
import math
import re
import shutil
import subprocess
import sys
import tempfile


def read_table(path):
    rows = [line.split('#')[0].split() for line in open(path)]
    rows = [r for r in rows if r]
    return int(rows[0][0]), rows[1:]


def main():
    deltri, src = sys.argv[1], sys.argv[2]
    work = tempfile.mkdtemp()
    for ext in ('smesh', 'node'):
        shutil.copy(f'{src}/tests/surface/inputs/pynastran_gear.{ext}', work)
    run = subprocess.run([deltri, '-pq30a20S5000C', 'pynastran_gear.smesh'], cwd=work, capture_output=True, text=True)
    if run.returncode != 0:
        sys.exit(f'deltri exited {run.returncode}: {run.stderr}')
    m = re.search(r'warning: the (?:facets did not agree|surface run spent its budget).*: (\d+) of (\d+) triangles below the -q angle, '
                  r'(\d+) above the -a area', run.stderr)
    if not m:
        sys.exit(f'no counted warning in: {run.stderr!r}')
    below, total, above = map(int, m.groups())
    n, rows = read_table(f'{work}/pynastran_gear.1.node')
    pts = {int(r[0]): tuple(float(x) for x in r[1:4]) for r in rows[:n]}
    m_tri, rows = read_table(f'{work}/pynastran_gear.1.ele')
    tris = [tuple(int(x) for x in r[1:4]) for r in rows[:m_tri]]

    def sub(p, q):
        return tuple(a - b for a, b in zip(p, q))

    def cross(u, v):
        return (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])

    def norm(u):
        return math.sqrt(sum(x * x for x in u))

    def angle(o, a, b):
        u, v = sub(a, o), sub(b, o)
        return math.degrees(math.atan2(norm(cross(u, v)), sum(x * y for x, y in zip(u, v))))

    my_below = my_above = 0
    for a, b, c in tris:
        A, B, C = pts[a], pts[b], pts[c]
        my_below += min(angle(A, B, C), angle(B, C, A), angle(C, A, B)) < 30.0
        my_above += 0.5 * norm(cross(sub(B, A), sub(C, A))) > 20.0
    print(f'warning: {below} of {total} below, {above} above; recomputed: {my_below} of {len(tris)}, {my_above}')
    if (below, total, above) != (my_below, len(tris), my_above):
        sys.exit('the warning does not count what the files hold')
    shutil.rmtree(work)


main()
