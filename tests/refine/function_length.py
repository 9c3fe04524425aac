#!/usr/bin/env python3
"""Issue 20's rule for src/refine/: no function of 40 lines or more, and the Terminator's core
(terminator_core.cpp, Figures 38-39 of the paper) under 150 lines with its paper lines cited.

A function is counted from the line its signature starts on (a line at column 0 that opens a
parenthesis and, on it or a following line, a body) to the closing brace at column 0, comments in
it included. usage: function_length.py SOURCE_DIR"""
import glob
import os
import re
import sys

LIMIT, CORE_LIMIT = 40, 150
SKIP = ("namespace", "struct", "class", "enum", "using", "template", "static_assert", "extern", "#")


def functions(path):
    lines = open(path, encoding="utf-8").read().split("\n")
    start = None
    for i, line in enumerate(lines):
        if start is None:
            if re.match(r"^[A-Za-z~].*\(", line) and not line.startswith(SKIP) and not line.rstrip().endswith(";"):
                j = i
                while j < len(lines) and not lines[j].rstrip().endswith(("{", ";", "}")):
                    j += 1
                if j < len(lines) and lines[j].rstrip().endswith("{"):
                    start = i
        elif line.startswith("}"):
            yield start + 1, i - start + 1, lines[start].strip()
            start = None


def main():
    refine = os.path.join(sys.argv[1], "src", "refine")
    failures = []
    for path in sorted(glob.glob(os.path.join(refine, "*.cpp")) + glob.glob(os.path.join(refine, "*.h"))):
        for line, length, signature in functions(path):
            if length >= LIMIT:
                failures.append(f"{os.path.basename(path)}:{line}: {length} lines: {signature}")
    core = os.path.join(refine, "terminator_core.cpp")
    text = open(core, encoding="utf-8").read()
    if text.count("\n") >= CORE_LIMIT:
        failures.append(f"terminator_core.cpp: {text.count(chr(10))} lines, the limit is {CORE_LIMIT}")
    cited = set(int(n) for n in re.findall(r"\bl\.(\d+)", text))
    cited |= {k for a, b in re.findall(r"\bl\.(\d+)-(\d+)", text) for k in range(int(a), int(b) + 1)}
    missing = [n for n in list(range(3, 26)) + list(range(36, 56)) if n not in cited]
    if missing:
        failures.append(f"terminator_core.cpp: Figure 38-39 lines not cited: {missing}")
    for failure in failures:
        print(failure)
    if failures:
        return 1
    print("every function in src/refine/ is under", LIMIT, "lines; the core cites every line of Figs. 38-39")
    return 0


sys.exit(main())
