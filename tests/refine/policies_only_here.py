#!/usr/bin/env python3
"""Issue 43's rule for the algorithm and the -Y / corner-lopping switches: they are read once, when
a Terminator is built, by the policy files (src/refine/algorithm*.h and .cpp, kept_boundary.*,
mending.*), and the rest of src/refine reads the policies' values. Anywhere else under src/refine,
code (not comments) that reads a member .algorithm, .no_steiner_on_segments (-Y, -YY),
.lopped_apices or .lopped_sectors (--corner-lopping) or .range_restricted, or that names a
RefinementAlgorithm:: value (outside refine.h, which declares the option), fails the test. The
Terminator's own files (refine/terminator*, and any other file that defines a Terminator:: member)
must not read .interior_bound (Sec. 7.2, --interior-bound) or .decline_cluster_splits either: they
come from AlgorithmPolicy (interior_strategy, declines_cluster_splits).

usage: policies_only_here.py SOURCE_DIR   (or --self-test: the rule must catch known forms)"""
import glob
import os
import re
import sys

READ = re.compile(r"\.\s*(algorithm|no_steiner_on_segments|lopped_apices|lopped_sectors|range_restricted)\b(?!\s*\()")
VALUE = re.compile(r"\bRefinementAlgorithm\s*::")
POLICY_FILES = re.compile(r"^refine/(algorithm[a-z_]*|kept_boundary|mending)\.(h|cpp)$")
DECLARES = ("refine/refine.h",)
TERMINATOR_READ = re.compile(r"\.\s*(interior_bound|decline_cluster_splits)\b(?!\s*\()")
TERMINATOR_FILES = re.compile(r"^refine/terminator[a-z_]*\.(h|cpp)$")
DEFINES_MEMBER = re.compile(r"\bTerminator\s*::")


def code(text):
    text = re.sub(r"/\*.*?\*/", lambda m: "\n" * m.group(0).count("\n"), text, flags=re.S)
    lines = []
    for line in text.split("\n"):
        line = re.sub(r'"(\\.|[^"\\])*"', '""', line)  # string literals
        lines.append(line.split("//")[0])
    return lines


def terminator_file(text, rel):
    return bool(TERMINATOR_FILES.match(rel)) or any(DEFINES_MEMBER.search(line) for line in code(text))


def violations(text, rel, terminator=False):
    found = []
    for number, line in enumerate(code(text), 1):
        if READ.search(line) or (rel not in DECLARES and VALUE.search(line)) or \
                (terminator and TERMINATOR_READ.search(line)):
            found.append((number, line.strip()))
    return found


def self_test():
    """The lines the rule answers wrongly (none when it works)."""
    caught = [
        "  if (opt_.algorithm == RefinementAlgorithm::Chew) return true;",
        "  const StagePlan plan = stage_plan(opt.algorithm);",
        "  return opt_.no_steiner_on_segments >= 2 || mesh_.link[e] == kNone;",
        "  if (opt_.lopped_apices && is_spoke(a, b)) return false;",
        "  const auto& sectors = *options.lopped_sectors;",
        "  if (opt_.range_restricted && !shell_a) return p;",
        "  const bool chew = algo == RefinementAlgorithm::Chew;",
    ]
    passed = [
        "  if (policy_.chew_ancestors && n != kNone) return true;",
        "  // opt_.algorithm is read by the policy files only",
        "  const char* s = \"opt.no_steiner_on_segments\";",
        "  if (lopping_.spares(mesh_, t)) a.skinny = false;",
        "  return range_restricted_split_point(pa, pb, top);",
        "  if (policy_.legal_lengths && !shell_a) return p;",
    ]
    terminator_caught = [
        "  if (opt_.interior_bound == 2 && !below_asked_bound(a))",
        "  return !opt_.decline_cluster_splits || split_permitted(mesh_, apices_, s, d);",
        "      interior_rules_{opt.interior_bound != 0 ? AngleBound(30.0) : opt.angle,",
    ]
    terminator_passed = [
        "  if (policy_.interior_strategy == 2 && !below_asked_bound(a))",
        "  return !policy_.declines_cluster_splits || split_permitted(mesh_, apices_, s, d);",
        "    case Outcome::InteriorBoundAtBottom: ++report.interior_bound_refusals; break;",
        "  // opt_.interior_bound is read by AlgorithmPolicy::of",
    ]
    files = [not terminator_file("x", "refine/terminator_policies.cpp"),
             not terminator_file("bool Terminator::f() { return true; }", "refine/x.cpp"),
             terminator_file("TerminatorStart TerminatorStart::of(m, o);", "refine/refine_in_parts.cpp")]
    return [l for l in caught if not violations(l, "refine/x.cpp")] + \
           [l for l in passed if violations(l, "refine/x.cpp")] + \
           [l for l in terminator_caught if not violations(l, "refine/x.cpp", True)] + \
           [l for l in terminator_passed if violations(l, "refine/x.cpp", True)] + \
           [f"terminator_file case {i}" for i, wrong in enumerate(files) if wrong]


def main():
    wrong = self_test()
    for line in wrong:
        print("self-test: wrong answer for:", line)
    if wrong or sys.argv[1:] == ["--self-test"]:
        return 1 if wrong else 0
    src = os.path.join(sys.argv[1], "src")
    paths = sorted(glob.glob(os.path.join(src, "refine", "**", "*.cpp"), recursive=True) +
                   glob.glob(os.path.join(src, "refine", "**", "*.h"), recursive=True))
    rels = [os.path.relpath(p, src).replace(os.sep, "/") for p in paths]
    if not any(POLICY_FILES.match(r) for r in rels) or not any(TERMINATOR_FILES.match(r) for r in rels):
        print("no policy files or no Terminator files under src/refine: the rule would pass vacuously")
        return 1
    failures = []
    for path in paths:
        rel = os.path.relpath(path, src).replace(os.sep, "/")
        if POLICY_FILES.match(rel):
            continue
        text = open(path, encoding="utf-8").read()
        for number, line in violations(text, rel, terminator_file(text, rel)):
            failures.append(f"src/{rel}:{number}: the algorithm, a -Y/lopping switch, or (in the Terminator's "
                            f"files) --interior-bound or --decline-cluster-splits read outside the policy "
                            f"files: {line}")
    for failure in failures:
        print(failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
