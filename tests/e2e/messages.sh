#!/bin/sh
# The exact text of messages a newcomer meets (issue 19), each against a fact from outside deltri:
#   messages.sh DELTRI DATA_DIR INPUTS_DIR VERSION      (VERSION: project(deltri VERSION ...) in CMake)
# --version and -V and the JSON report against CMake's version; -a-1 and -q-5 (exit 2, nothing
# written); a bare -a with and without regional area bounds; an output named like the input (exit
# 4, input untouched); -h on -s; the JSON's Steiner counts against the vertex counts of the input
# and output .node files; an empty mesh's null angle and its -V text.
set -u
deltri=$1 data=$2 inputs=$3 version=$4
work=$(mktemp -d) || exit 1
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
cp "$data/box.poly" "$data/guitar.poly" "$data/crossing-edges.poly" "$inputs/plate.poly" .
failed=0
fail() { echo "FAIL: $*"; failed=1; }

# expect STATUS STDOUT STDERR -- ARGS...: the exit status and both streams exactly.
expect() {
  want_status=$1 want_out=$2 want_err=$3
  shift 4
  "$deltri" "$@" >out 2>err
  status=$?
  [ "$status" = "$want_status" ] || fail "deltri $*: exit $status, expected $want_status"
  [ "$(cat out)" = "$want_out" ] || fail "deltri $*: stdout was '$(cat out)', expected '$want_out'"
  [ "$(cat err)" = "$want_err" ] || fail "deltri $*: stderr was '$(cat err)', expected '$want_err'"
}
# The files here besides the inputs (a refused run writes none).
outputs() { ls | grep -v -x -e box.poly -e guitar.poly -e crossing-edges.poly -e plate.poly -e out -e err | tr '\n' ' '; }

expect 0 "deltri $version" "" -- --version
expect 2 "" "deltri: -a-1: the maximum area must be a positive number, e.g. -a0.1" -- -pa-1 box.poly
expect 2 "" "deltri: -q-5: the minimum angle must be at least 0 and below 60 degrees" -- -pq-5 box.poly
# Triangle refuses -a0 too, with exit status 1.
expect 1 "" "deltri: -a: the maximum area must be a positive number, e.g. -a0.1" -- -pa0 box.poly
[ -z "$(outputs)" ] || fail "a refused switch wrote $(outputs)"
cp box.poly box.orig
expect 4 "" "box.poly: is an input of this run, not overwritten (no files written)" -- -pQ --msh=box.poly box.poly
cmp -s box.poly box.orig || fail "--msh=box.poly changed box.poly"
rm box.orig
[ -z "$(outputs)" ] || fail "a refused output wrote $(outputs)"
expect 0 "" "deltri: warning: box.poly: bare -a has no effect: the input has no regional area bounds (-a<area> bounds every triangle)" -- -paQ box.poly
# plate.poly's regions bound the area: the bare -a applies, no warning.
expect 0 "" "" -- -paQ plate.poly
"$deltri" -h >out
grep -q -x -- "  -s          insert segments by splitting them at midpoints (conforming), not by flips" out ||
  fail "-h on -s: $(grep -- '^  -s' out)"

# -V: the version line right after the summary line; the JSON report carries the same version.
"$deltri" -pq30V --json guitar.poly >out 2>err || fail "-pq30V guitar.poly failed"
[ "$(sed -n 2p out)" = "deltri $version" ] || fail "-V: second line was '$(sed -n 2p out)'"
grep -q "^{\"program\":\"deltri\",\"version\":\"$version\"," guitar.1.json || fail "the JSON report does not start with the version: $(head -c 80 guitar.1.json)"

# Steiner points: inserted - deleted = kept = the output .node's vertices - the input's (guitar has
# no duplicates and no crossings, so refinement made every new vertex). -q32 deletes some (from
# -q33 the locally optimal points, refinement.md, delete none on guitar).
"$deltri" -pq32Q --json guitar.poly || fail "-pq32 guitar.poly failed"
count() { awk '!/^[[:space:]]*(#|$)/ { print $1; exit }' "$1"; }
added=$(($(count guitar.1.node) - $(count guitar.poly)))
/usr/bin/python3 - "$added" <<'EOF' || failed=1
import json, sys
m = json.load(open("guitar.1.json"))["mesh"]
added = int(sys.argv[1])
ok = m["steiner_points"] - m["steiner_points_deleted"] == m["steiner_points_kept"] == added and m["steiner_points_deleted"] > 0
print(("" if ok else "FAIL: ") + f"-pq32 guitar.poly: steiner_points {m['steiner_points']}, deleted {m['steiner_points_deleted']}, kept {m['steiner_points_kept']}; the .node files differ by {added} vertices")
sys.exit(0 if ok else 1)
EOF

# An empty mesh: no angle at all (null), and -V says why there are no shape figures.
"$deltri" -pV --json crossing-edges.poly >out 2>err || fail "-pV crossing-edges.poly failed"
grep -q '"triangles":0,' crossing-edges.1.json || fail "crossing-edges.poly: the mesh is not empty"
grep -q '"smallest_angle":null,"largest_angle":null,' crossing-edges.1.json ||
  fail "empty mesh: $(grep -o '"smallest_angle":[^,]*' crossing-edges.1.json)"
grep -q -x "  No triangles, so no shape statistics." out || fail "empty mesh: -V says $(cat out)"
grep -q -x "deltri: warning: crossing-edges.poly: every triangle lies outside the segments or in a hole: the mesh is empty (try -c or -O)" err ||
  fail "empty mesh: stderr was $(cat err)"

[ $failed = 0 ] && echo "messages: --version, -V and JSON carry $version; -a-1, -q-5, -a0, --msh=<input>, bare -a, -h -s, Steiner counts and the empty mesh as documented"
exit $failed
