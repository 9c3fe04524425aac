"""The C client (tests/api/c_client.c) against the command line on the same input and switches.

    compare_c_client.py DELTRI C_CLIENT WORKDIR INPUT SWITCHES [SWITCHES2] [--preallocate]

Writes INPUT's arrays for the client (numbered as Triangle's library numbers them: from 0 with z,
else from 1), runs the client and deltri -SWITCHES INPUT (and, with SWITCHES2, deltri -SWITCHES2
on the .1 files it wrote, as the client refines its own first output), then reads deltri's .node,
.ele, .poly, .edge, .neigh, .v.node and .v.edge and requires every array the client got to be the
same, value for value (the files hold the shortest decimals that read back as the same doubles),
and every file deltri wrote to have its array. Exit 0 when all agree."""
import os
import shutil
import subprocess
import sys


def lines(path):
    out = []
    for raw in open(path):
        fields = raw.split('#')[0].split()
        if fields:
            out.append(fields)
    return out


def read_previous_mesh(path):
    """An .ele named as input (r): its .node's arrays, its triangles and attributes, its .area."""
    base = path[:-len('.ele')]
    a, first = read_poly_or_node(base + '.node')
    L = lines(path)
    t, c, na = (int(x) for x in (L[0] + ['3', '0'])[:3])
    a['triangles'] = [[int(x) for x in f[1:1 + c]] for f in L[1:1 + t]]
    if na:
        a['triangle_attributes'] = [[float(x) for x in f[1 + c:1 + c + na]] for f in L[1:1 + t]]
    if os.path.exists(base + '.area'):
        a['triangle_areas'] = [[float(f[1])] for f in lines(base + '.area')[1:]]
    return a, first


def read_poly_or_node(path):
    """The input arrays of a .node or .poly, with the file's first index."""
    if path.endswith('.ele'):
        return read_previous_mesh(path)
    L = lines(path)
    n, _, na, nm = (int(x) for x in (L[0] + ['2', '0', '0'])[:4])
    first = int(L[1][0])
    a = {'points': [], 'point_attributes': [], 'point_markers': []}
    for f in L[1:1 + n]:
        a['points'].append([float(f[1]), float(f[2])])
        a['point_attributes'].append([float(x) for x in f[3:3 + na]])
        if nm:
            a['point_markers'].append([int(f[3 + na])])
    k = 1 + n
    if path.endswith('.poly'):
        ns, sm = (int(x) for x in (L[k] + ['0'])[:2])
        a['segments'] = [[int(f[1]), int(f[2])] for f in L[k + 1:k + 1 + ns]]
        if sm:
            a['segment_markers'] = [[int(f[3])] for f in L[k + 1:k + 1 + ns]]
        k += 1 + ns
        nh = int(L[k][0])
        a['holes'] = [[float(f[1]), float(f[2])] for f in L[k + 1:k + 1 + nh]]
        k += 1 + nh
        if k < len(L):
            nr = int(L[k][0])
            a['regions'] = [[float(x) for x in f[1:5]] for f in L[k + 1:k + 1 + nr]]
    return a, first


def write_flat(path, arrays):
    with open(path, 'w') as f:
        for name, rows in arrays.items():
            if not rows or not rows[0]:
                continue
            f.write('%s %d %d\n' % (name, len(rows), len(rows[0])))
            for r in rows:
                f.write(' '.join(repr(x) for x in r) + '\n')


def read_flat(path):
    tokens = open(path).read().split()
    out, i = {}, 0
    while i < len(tokens):
        name = tokens[i]
        if name == 'counts':
            out['counts'] = [int(x) for x in tokens[i + 1:i + 9]]
            i += 9
            continue
        rows, cols = int(tokens[i + 1]), int(tokens[i + 2])
        vals = tokens[i + 3:i + 3 + rows * cols]
        out[name] = [[float(v) for v in vals[r * cols:(r + 1) * cols]] for r in range(rows)]
        i += 3 + rows * cols
    return out


def cli_arrays(stem, renumber):
    """deltri's files for stem (e.g. work/plate.1) as arrays; vertex and triangle numbers renumbered."""
    got = {}
    if os.path.exists(stem + '.node'):
        L = lines(stem + '.node')
        n, _, na, nm = (int(x) for x in L[0][:4])
        got['points'] = [[float(f[1]), float(f[2])] for f in L[1:1 + n]]
        if na:
            got['point_attributes'] = [[float(x) for x in f[3:3 + na]] for f in L[1:1 + n]]
        if nm:
            got['point_markers'] = [[float(f[3 + na])] for f in L[1:1 + n]]
    if os.path.exists(stem + '.ele'):
        L = lines(stem + '.ele')
        t, c, na = (int(x) for x in L[0][:3])
        got['triangles'] = [[renumber(int(x)) for x in f[1:1 + c]] for f in L[1:1 + t]]
        if na:
            got['triangle_attributes'] = [[float(x) for x in f[1 + c:1 + c + na]] for f in L[1:1 + t]]
    if os.path.exists(stem + '.neigh'):
        L = lines(stem + '.neigh')
        got['neighbors'] = [[renumber(int(x)) if int(x) >= 0 else -1 for x in f[1:4]] for f in L[1:]]
    if os.path.exists(stem + '.poly'):
        L = lines(stem + '.poly')
        ns, sm = (int(x) for x in L[1][:2])
        got['segments'] = [[renumber(int(f[1])), renumber(int(f[2]))] for f in L[2:2 + ns]]
        if sm:
            got['segment_markers'] = [[float(f[3])] for f in L[2:2 + ns]]
    if os.path.exists(stem + '.edge'):
        L = lines(stem + '.edge')
        ne, em = (int(x) for x in L[0][:2])
        got['edges'] = [[renumber(int(f[1])), renumber(int(f[2]))] for f in L[1:1 + ne]]
        if em:
            got['edge_markers'] = [[float(f[3])] for f in L[1:1 + ne]]
    if os.path.exists(stem + '.v.node'):
        L = lines(stem + '.v.node')
        n, _, na = (int(x) for x in L[0][:3])
        got['voronoi_points'] = [[float(f[1]), float(f[2])] for f in L[1:1 + n]]
        if na:
            got['voronoi_point_attributes'] = [[float(x) for x in f[3:3 + na]] for f in L[1:1 + n]]
    if os.path.exists(stem + '.v.edge'):
        L = lines(stem + '.v.edge')
        got['voronoi_edges'] = [[renumber(int(f[1])), renumber(int(f[2])) if int(f[2]) >= 0 else -1] for f in L[1:]]
        got['voronoi_normals'] = [[float(f[3]), float(f[4])] if int(f[2]) < 0 else [0.0, 0.0] for f in L[1:]]
    return got


def main():
    deltri, client, work, source, switches = sys.argv[1:6]
    rest = sys.argv[6:]
    prealloc = '--preallocate' in rest
    second = [a for a in rest if a != '--preallocate']
    second = second[0] if second else None
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    name = os.path.basename(source)
    for ext in ('.node', '.area'):  # beside a named .ele
        if source.endswith('.ele') and os.path.exists(source[:-4] + ext):
            shutil.copy(source[:-4] + ext, work)
    shutil.copy(source, work)
    stem_in = os.path.join(work, name.rsplit('.', 1)[0])
    arrays, first = read_poly_or_node(source)
    lib_first = 0 if 'z' in (second or switches) else 1
    in_first = 0 if 'z' in switches else 1
    shift = in_first - first
    for key in ('segments', 'triangles'):
        if key in arrays:
            arrays[key] = [[v + shift for v in r] for r in arrays[key]]
    write_flat(os.path.join(work, 'input.flat'), arrays)
    cmd = [client, os.path.join(work, 'input.flat'), os.path.join(work, 'output.flat'), switches]
    cmd += ([second] if second else []) + (['--preallocate'] if prealloc else [])
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode != 0 or r.stderr:
        sys.exit('FAIL: c_client %s: exit %d, stderr %r' % (' '.join(cmd[3:]), r.returncode, r.stderr))
    subprocess.run([deltri, '-' + switches, name], cwd=work, check=True, capture_output=True)
    # The output's iteration number follows the input's (box.1.ele -> box.2.*), as in Triangle.
    parts = stem_in.rsplit('.', 1)
    stem = parts[0] + '.%d' % (int(parts[1]) + 1) if len(parts) == 2 and parts[1].isdigit() else stem_in + '.1'
    # As in Triangle, the input's own first index (0 or 1) numbers the files, -z or not.
    cli_first = first
    if second:
        subprocess.run([deltri, '-' + second, os.path.basename(stem)], cwd=work, check=True, capture_output=True)
        stem = stem_in + '.2'
    got = read_flat(os.path.join(work, 'output.flat'))
    want = cli_arrays(stem, lambda v: v - cli_first + lib_first)
    failures = []
    for key, rows in want.items():
        if key not in got:
            failures.append('%s: in deltri\'s files, not from the library' % key)
        elif got[key] != rows:
            bad = next(i for i in range(min(len(rows), len(got[key])) + 1)
                       if i >= len(rows) or i >= len(got[key]) or rows[i] != got[key][i])
            failures.append('%s: %d rows from the library, %d in the files; first difference at row %d' %
                            (key, len(got[key]), len(rows), bad))
    for key in got:
        if key not in want and key not in ('counts', 'holes', 'regions'):
            failures.append('%s: from the library, not in deltri\'s files' % key)
    counts = got['counts']
    if 'points' in want and counts[0] != len(want['points']):
        failures.append('numberofpoints %d, the .node has %d' % (counts[0], len(want['points'])))
    if 'triangles' in want and counts[2] != len(want['triangles']):
        failures.append('numberoftriangles %d, the .ele has %d' % (counts[2], len(want['triangles'])))
    if 'edges' in want and counts[6] != len(want['edges']):
        failures.append('numberofedges %d, the .edge has %d' % (counts[6], len(want['edges'])))
    final = second or switches
    if 'p' in final and 'r' not in final and 'holes' in arrays and got.get('holes', []) != arrays['holes']:
        failures.append('out->holelist is not the input\'s holes')
    label = '-' + switches + (' then -' + second if second else '') + (' (caller-allocated outputs too)' if prealloc else '')
    if failures:
        print('FAIL %s on %s:\n  %s' % (label, name, '\n  '.join(failures)))
        sys.exit(1)
    print('ok %s on %s: %s agree' % (label, name, ', '.join(sorted(want))))


main()
