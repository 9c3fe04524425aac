#!/usr/bin/env python3
"""The build enforces the layers: for each layer (a folder of src/, a target deltri_<folder>), the
include path its sources are compiled with must reach the headers of exactly the layers below it
in CMakeLists.txt's graph (the deltri_layer() lines, which docs.layer_table holds equal to
docs/architecture.md's table), followed transitively, and of no other layer. Each layer is tried
against every other: a one-line source including a header of that layer is preprocessed with the
layer's own include directories (as the build generated them); it must fail exactly when the
included layer is not below. So an include that points up a layer fails to build, and this test
fails if the build stops making it fail (src/ put on a layer's path, a link added the wrong way).

    build_layers.py SOURCE_DIR CXX INCLUDE_DIRS_FILE

INCLUDE_DIRS_FILE has one line per layer: `name:dir1;dir2;...` (tests/CMakeLists.txt writes it).
"""
import os, re, subprocess, sys, tempfile
from concurrent.futures import ThreadPoolExecutor

root, cxx, dirs_file = sys.argv[1:4]
src = os.path.join(root, 'src')

graph = {}  # layer -> the layers its deltri_layer() line names
order = []
for line in open(os.path.join(root, 'CMakeLists.txt')):
    m = re.match(r'\s*deltri_layer\(([a-z_]+)((?:\s+[a-z_]+)*)\)', line)
    if m:
        graph[m.group(1)] = m.group(2).split()
        order.append(m.group(1))
if not graph:
    sys.exit("FAIL: no deltri_layer() lines in CMakeLists.txt")

def below(layer, seen=None):
    seen = set() if seen is None else seen
    for d in graph[layer]:
        if d not in seen:
            seen.add(d)
            below(d, seen)
    return seen

include_dirs = {}
for line in open(dirs_file):
    name, _, dirs = line.rstrip('\n').partition(':')
    include_dirs[name] = [d for d in dirs.split(';') if d]

def probe_header(layer):
    """The smallest header of a layer, as its users name it."""
    if layer == 'api':
        return 'deltri/triangle.h'
    headers = [f for f in os.listdir(os.path.join(src, layer)) if f.endswith('.h')]
    headers.sort(key=lambda f: (os.path.getsize(os.path.join(src, layer, f)), f))
    return f'{layer}/{headers[0]}'

def preprocesses(args):
    """Whether a source holding only `#include "header"` preprocesses with the given flags."""
    flags, header, tmp = args
    probe = os.path.join(tmp, header.replace('/', '_') + str(abs(hash(tuple(flags)))) + '.cpp')
    with open(probe, 'w') as f:
        f.write(f'#include "{header}"\n')
    r = subprocess.run([cxx, *flags, '-E', '-o', os.devnull, probe], capture_output=True, text=True)
    return r.returncode == 0, (r.stderr.strip().splitlines() or ['?'])[0]

faults = []
jobs = []  # (layer, other, header, flags)
for layer in order:
    if layer not in include_dirs:
        faults.append(f"deltri_{layer}: no include directories in {dirs_file}")
        continue
    if os.path.realpath(src) in map(os.path.realpath, include_dirs[layer]):
        faults.append(f"deltri_{layer}: src/ itself is on its include path")
    flags = ['-std=c++20'] + [f'-I{d}' for d in include_dirs[layer]]
    jobs += [(layer, other, probe_header(other), flags) for other in order]
with tempfile.TemporaryDirectory() as tmp, ThreadPoolExecutor(max_workers=2) as pool:
    results = list(pool.map(preprocesses, [(flags, header, tmp) for _, _, header, flags in jobs]))
tried = len(jobs)
for (layer, other, header, _), (ok, first) in zip(jobs, results):
    allowed = other == layer or other in below(layer)
    if allowed and not ok:
        faults.append(f"deltri_{layer} cannot include {header} of a layer below it: {first}")
    elif not allowed and ok:
        faults.append(f"deltri_{layer} can include {header}, of src/{other}/, which is not below it")
for f in faults:
    print("FAIL:", f)
if not faults:
    print(f"{len(order)} layers, {tried} includes tried: each layer reaches exactly the layers below it")
sys.exit(1 if faults else 0)
