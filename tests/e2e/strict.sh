#!/bin/sh
# --strict on meshes a solver should not be handed silently:
#   strict.sh DELTRI INPUT SWITCHES EXPECTED_EXIT WARNING JSON_CHECK
# Runs deltri SWITCHES --strict --json INPUT in a fresh directory; the exit status must be
# EXPECTED_EXIT, stderr must hold the line WARNING, the mesh files must still be written, and the
# JSON report (read by python3's json) must satisfy the Python expression JSON_CHECK on `q`
# (its "quality" object) and `m` (its "mesh" object). Beyond that, for every case:
#   * the JSON's counts of triangles below the -q angle and above the -a area equal the counts
#     computed here from the .node/.ele (the causes must add up to the total);
#   * a run refused for misses the input does not force names them in a warning, exactly (the
#     line's numbers are the JSON's), unless refinement's own "triangles miss" warning does;
#   * misses forced at crossings of input segments are said in a warning, exactly, and only then;
#   * the same run with -V prints the same counts in its "Bounds (final mesh)" lines.
set -u
deltri=$1 input=$2 switches=$3 expect=$4 warning=$5 json_check=$6
work=$(mktemp -d) || exit 1
trap 'rm -rf "$work"' EXIT
cp "$input" "$work/" || exit 1
name=$(basename "$input")
stem=${name%.*}
cd "$work" || exit 1
# shellcheck disable=SC2086
"$deltri" $switches --strict --json "$name" >stdout 2>stderr
status=$?
sed 's/^/  stderr: /' stderr
fail() { echo "FAIL: $*"; exit 1; }
[ "$status" = "$expect" ] || fail "exit status $status, expected $expect"
grep -F -x -q -- "$warning" stderr || fail "stderr lacks the line '$warning'"
[ -s "$stem.1.ele" ] && [ -s "$stem.1.node" ] || fail "--strict did not write the mesh"
mkdir verbose && cp "$name" verbose/ || exit 1
# shellcheck disable=SC2086
(cd verbose && "$deltri" $switches -V "$name" >report 2>&1)
/usr/bin/python3 - "$stem.1" "$name" "$json_check" "$expect" <<'PY' || exit 1
import json, math, re, sys
base, name, json_check, expect = sys.argv[1:5]
report = json.load(open(base + ".json"))
q, m = report["quality"], report["mesh"]
def fail(message):
    sys.exit(f"FAIL: {message}")
if report["exit_status"] != int(expect):
    fail(f"JSON exit_status {report['exit_status']}")
causes = q["missing_bounds_by_cause"]
if sum(causes.values()) != q["triangles_missing_bounds"]:
    fail(f"the causes {causes} do not add up to {q['triangles_missing_bounds']}")
if q["triangles_missing_bounds_not_forced_by_input"] != q["triangles_missing_bounds"] - causes["small_input_angle"]:
    fail("triangles_missing_bounds_not_forced_by_input is not the total less small_input_angle")
# The angle count recomputed from the written mesh (a band of 1e-9 relative around the bound, where
# this float arithmetic and deltri's may round differently).
def rows(path):
    for line in open(path):
        line = line.split("#", 1)[0].split()
        if line:
            yield line
nodes = rows(base + ".node")
n = int(next(nodes)[0])
points = {int(t[0]): (float(t[1]), float(t[2])) for t in (next(nodes) for _ in range(n))}
eles = rows(base + ".ele")
count = int(next(eles)[0])
def smallest_angle(a, b, c):
    def at(p, r, s):
        ux, uy, vx, vy = r[0] - p[0], r[1] - p[1], s[0] - p[0], s[1] - p[1]
        return math.degrees(math.atan2(abs(ux * vy - uy * vx), ux * vx + uy * vy))
    return min(at(a, b, c), at(b, c, a), at(c, a, b))
corners = [[points[int(v)] for v in t[1:4]] for t in (next(eles) for _ in range(count))]
angles = [smallest_angle(*c) for c in corners]
areas = [abs((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])) / 2 for a, b, c in corners]
if q["min_angle_bound"] is not None:
    bound = q["min_angle_bound"]
    low = sum(a < bound * (1 - 1e-9) for a in angles)
    high = sum(a < bound * (1 + 1e-9) for a in angles)
    if not low <= q["triangles_below_angle_bound"] <= high:
        fail(f"JSON: {q['triangles_below_angle_bound']} triangles below {bound} degrees; the .ele has {low} (to {high})")
    print(f"  .ele: {low} of {count} triangles below {bound} degrees, as the JSON says")
if q["max_area_bound"] is not None and q["max_edge_length_bound"] is None:
    bound = q["max_area_bound"]
    low = sum(a > bound * (1 + 1e-9) for a in areas)
    high = sum(a > bound * (1 - 1e-9) for a in areas)
    if not low <= q["triangles_above_size_bound"] <= high:
        fail(f"JSON: {q['triangles_above_size_bound']} triangles above the area {bound}; the .ele has {low} (to {high})")
    print(f"  .ele: {low} of {count} triangles above the area {bound}, as the JSON says")
stderr = open("stderr").read().splitlines()
refine_line = re.compile(rf"deltri: warning: {re.escape(name)}: \d+ triangles? miss(es)? the requested bounds(,| \()")
reason = (f"deltri: warning: {name}: {q['triangles_missing_bounds_not_forced_by_input']} "
          f"{'triangle misses' if q['triangles_missing_bounds_not_forced_by_input'] == 1 else 'triangles miss'} the requested "
          f"bounds for a reason other than a small input angle ({causes['repaired_crossing_or_overlap']} next to repaired "
          f"crossings or overlaps, {causes['double_precision']} at the limit of double precision, "
          f"{causes['steiner_limits']} at -S/-Y limits, {causes['other']} other)")
if q["triangles_missing_bounds_not_forced_by_input"] > 0 and reason not in stderr and not any(refine_line.match(l) for l in stderr):
    fail(f"stderr lacks the line '{reason}'")
crossings = q["triangles_missing_bounds_at_input_crossings"]
if crossings > causes["small_input_angle"] + causes.get("large_input_angle", 0):
    fail(f"{crossings} misses at crossings of input segments, more than the {causes} forced by input angles")
said = (f"deltri: warning: {name}: {crossings} {'triangle misses' if crossings == 1 else 'triangles miss'} the requested "
        f"bounds next to crossings of input segments, forced by the angles the segments cross at")
if (said in stderr) != (crossings > 0):
    fail(f"stderr {'lacks' if crossings else 'has'} the line '{said}'")
verbose = open("verbose/report").read()
want = (f"Bounds (final mesh): {q['triangles_missing_bounds']} triangles miss them ({q['triangles_below_angle_bound']} below the angle, "
        f"{q['triangles_above_size_bound']} above the size)\n  by cause: {causes['small_input_angle']} next to a small input angle, "
        f"{causes['repaired_crossing_or_overlap']} next to a repaired crossing or overlap, {causes['double_precision']} at the limit "
        f"of double precision, {causes['steiner_limits']} at -S/-Y limits, {causes['other']} other\n")
if crossings:
    want += f"  of those forced by input angles, {crossings} at crossings of input segments\n"
if want not in verbose:
    fail(f"-V does not print the JSON's counts:\n{want}")
if not eval(json_check):
    fail(f"the JSON fails {json_check}: {q}")
print(f"  JSON and -V: {q['triangles_missing_bounds']} of {m['triangles']} triangles miss the bounds: {causes}")
PY
echo "ok"
