#!/usr/bin/env python3
"""docs/architecture.md's layer table against the sources and the build: for each src/ folder, the
"knows about" column must list exactly the other src/ folders whose headers its files include
("nothing" for none), so that the table stays true when an include is added or removed; the rows
are the layers lowest first, so no folder may include one of a row below its own (an include
pointing up a layer); and the table must be CMakeLists.txt's layer graph (its deltri_layer()
lines, the targets whose include paths make such an include fail to compile: build.layers).

    layer_table.py SOURCE_DIR

An include is `#include "X/..."` with X a folder of src/ (`deltri/...` is the library's public
headers in src/api); an include of the folder's own files is not a dependency.
"""
import os, re, sys

root = sys.argv[1]
src = os.path.join(root, 'src')
folders = sorted(d for d in os.listdir(src) if os.path.isdir(os.path.join(src, d)))

actual = {d: {} for d in folders}  # folder -> {included folder: first file that includes it}
for d in folders:
    for dirpath, _, files in os.walk(os.path.join(src, d)):
        for name in sorted(files):
            if not name.endswith(('.h', '.hpp', '.c', '.cc', '.cpp')):
                continue
            path = os.path.join(dirpath, name)
            with open(path, errors='replace') as f:
                for line in f:
                    m = re.match(r'\s*#\s*include\s*"([^"/]+)/', line)
                    if not m:
                        continue
                    top = 'api' if m.group(1) == 'deltri' else m.group(1)
                    if top in actual and top != d:
                        actual[d].setdefault(top, os.path.relpath(path, root))

doc = open(os.path.join(root, 'docs', 'architecture.md')).read().split('\n')
start = doc.index('| directory | job | knows about |')
table = {}
rows = []
for line in doc[start + 2:]:
    if not line.startswith('|'):
        break
    cells = [c.strip() for c in line.strip('|').split('|')]
    m = re.fullmatch(r'`src/([a-z_]+)/`', cells[0])
    if not m:
        sys.exit(f"architecture.md: a layer row without a `src/NAME/` first cell: {line[:80]}")
    listed = cells[-1]
    table[m.group(1)] = set() if listed == 'nothing' else {w.strip() for w in listed.split(',')}
    rows.append(m.group(1))

cmake = {}
cmake_order = []
for line in open(os.path.join(root, 'CMakeLists.txt')):
    m = re.match(r'\s*deltri_layer\(([a-z_]+)((?:\s+[a-z_]+)*)\)', line)
    if m:
        cmake[m.group(1)] = set(m.group(2).split())
        cmake_order.append(m.group(1))

faults = []
for d in folders:
    if d not in table:
        faults.append(f"src/{d}/ has no row in the table")
        continue
    unknown = sorted(table[d] - set(folders))
    if unknown:
        faults.append(f"src/{d}/: the table names {', '.join(unknown)}, which are not folders of src/")
    for missing in sorted(set(actual[d]) - table[d]):
        faults.append(f"src/{d}/ includes {missing}/ ({actual[d][missing]}), which its row does not list")
    for extra in sorted(table[d] - set(actual[d]) - set(unknown)):
        faults.append(f"src/{d}/'s row lists {extra}, which none of its files includes")
    for up in sorted(t for t in actual[d] if t in rows and d in rows and rows.index(t) > rows.index(d)):
        faults.append(f"src/{d}/ includes {up}/ ({actual[d][up]}), a layer above it (a later row of the table)")
    if d not in cmake:
        faults.append(f"src/{d}/ has no deltri_layer() line in CMakeLists.txt")
    elif d in table and cmake[d] != table[d]:
        faults.append(f"src/{d}/: CMakeLists.txt's deltri_layer() names {', '.join(sorted(cmake[d])) or 'nothing'}, "
                      f"the table {', '.join(sorted(table[d])) or 'nothing'}")
if [r for r in rows if r in cmake] != [c for c in cmake_order if c in table]:
    faults.append("the table's rows and CMakeLists.txt's deltri_layer() lines are in different orders")
for d in sorted(set(table) - set(folders)):
    faults.append(f"the table has a row for src/{d}/, which does not exist")
for f in faults:
    print("FAIL:", f)
if not faults:
    print(f"docs/architecture.md's layer table matches the includes of {len(folders)} folders, lowest first, and the build's layers")
sys.exit(1 if faults else 0)
