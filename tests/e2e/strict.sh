#!/bin/sh
# --strict on meshes a solver should not be handed silently:
#   strict.sh DELTRI INPUT SWITCHES EXPECTED_EXIT WARNING JSON_CHECK
# Runs deltri SWITCHES --strict --json INPUT in a fresh directory; the exit status must be
# EXPECTED_EXIT, stderr must hold the line WARNING, the mesh files must still be written, and the
# JSON report (read by python3's json) must satisfy the Python expression JSON_CHECK on `q`
# (its "quality" object) and `m` (its "mesh" object).
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
/usr/bin/python3 - "$stem.1.json" "$json_check" "$expect" <<'PY' || exit 1
import json, sys
report = json.load(open(sys.argv[1]))
q, m = report["quality"], report["mesh"]
if report["exit_status"] != int(sys.argv[3]):
    sys.exit(f"FAIL: JSON exit_status {report['exit_status']}")
causes = q["missing_bounds_by_cause"]
if sum(causes.values()) != q["triangles_missing_bounds"]:
    sys.exit(f"FAIL: the causes {causes} do not add up to {q['triangles_missing_bounds']}")
if not eval(sys.argv[2]):
    sys.exit(f"FAIL: the JSON fails {sys.argv[2]}: {q}")
print(f"  JSON: {q['triangles_missing_bounds']} of {m['triangles']} triangles miss the bounds: {causes}")
PY
echo "ok"
