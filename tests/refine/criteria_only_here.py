#!/usr/bin/env python3
"""Issue 43's rule: "is this angle below the bound" is answered in one place, the criteria
(src/refine/criteria.h and .cpp). Anywhere else in src/, a comparison (<, >, <=, >=) one of whose
operands names an angle bound (an AngleBound's sin2() or degrees(), a sin2_theta, a member bound
such as kept_bound_sin2_, a ratio2_over_bound2, the -q switch's min_angle) and whose other operand
is not a plain number (a check that the bound is on) fails the test: such code calls the
criteria's below_angle, meets_angle, below_other_bound, below_angle_bound or BoundCheck instead.

usage: criteria_only_here.py SOURCE_DIR   (or --self-test: the rule must catch known forms)"""
import glob
import os
import re
import sys

BOUND = re.compile(r"(sin2\(\)|\.degrees\(\)|sin2_theta|_sin2_\b|ratio2_over_bound2|\bmin_angle\b)")
OPERATOR = re.compile(r"(?<![<>=!-])(<=|>=|<|>)(?![<>=])")
NUMBER = re.compile(r"^[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?$")
STOPS = ("&&", "||", "+=", "-=", "return", "?", ",", ";", "=", "!", ":")
OWNERS = ("refine/criteria.h", "refine/criteria.cpp")


def code(line):
    line = re.sub(r'"(\\.|[^"\\])*"', '""', line)  # string literals
    return line.split("//")[0]


def operand(text, step):
    """The operand next to a comparison: text read away from the operator (step -1: leftwards)
    until an unbalanced bracket or a lower-precedence token."""
    depth, out = 0, []
    i = len(text) - 1 if step < 0 else 0
    while 0 <= i < len(text):
        ch = text[i]
        opening, closing = ("(", ")") if step > 0 else (")", "(")
        if ch in "([{" if step > 0 else ch in ")]}":
            depth += 1
        elif ch in ")]}" if step > 0 else ch in "([{":
            if depth == 0:
                break
            depth -= 1
        elif depth == 0:
            ahead = text[i:] if step > 0 else text[:i + 1]
            if any((ahead.startswith(t) if step > 0 else ahead.endswith(t)) for t in STOPS):
                break
        out.append(ch)
        i += step
    word = "".join(out if step > 0 else reversed(out)).strip()
    return word


def violations(text):
    found = []
    for number, line in enumerate(text.split("\n"), 1):
        body = code(line)
        if body.lstrip().startswith(("#", "template")):
            continue
        for m in OPERATOR.finditer(body):
            sides = (operand(body[:m.start()], -1), operand(body[m.end():], 1))
            if any(BOUND.search(s) for s in sides) and not any(NUMBER.match(s) for s in sides):
                found.append((number, line.strip()))
                break
    return found


def self_test():
    caught = [
        "    tally.below_angle += sine2 < kept_bound_sin2_;",
        "  return a.skinny && a.shape.ratio2_over_bound2 * opt_.angle.sin2() > interior_rules_.angle.sin2();",
        "    if (smallest_angle_sine2(p, q, Point{x, y}) >= sin2_theta) return false;",
        "    result.below_angle += sw.quality && surface_smallest_angle(p[0], p[1], p[2]) < sw.min_angle;",
        "  if (angle_at(a, b, c) < r.angle.degrees()) ++misses;",
    ]
    passed = [
        "  if (!(sin2_theta > 0.0)) return 0;",
        "  if (s.quality && !(s.min_angle >= 0.0 && s.min_angle < 60.0))",
        "  std::vector<double> xs;  // sin2() < x in a comment",
        "  tally.below_angle += below_angle(sine2, kept_bound_sin2_);",
    ]
    bad = [l for l in caught if not violations(l)] + [l for l in passed if violations(l)]
    for line in bad:
        print("self-test: wrong answer for:", line)
    return 1 if bad else 0


def main():
    if sys.argv[1:] == ["--self-test"]:
        return self_test()
    if self_test():
        return 1
    src = os.path.join(sys.argv[1], "src")
    failures = []
    for path in sorted(glob.glob(os.path.join(src, "**", "*.cpp"), recursive=True) +
                       glob.glob(os.path.join(src, "**", "*.h"), recursive=True)):
        rel = os.path.relpath(path, src).replace(os.sep, "/")
        if rel in OWNERS:
            continue
        for number, line in violations(open(path, encoding="utf-8").read()):
            failures.append(f"src/{rel}:{number}: an angle compared against a bound outside the criteria: {line}")
    for failure in failures:
        print(failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
