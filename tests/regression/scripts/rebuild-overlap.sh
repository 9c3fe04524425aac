#!/bin/sh
# Issue 17 item 2: -r must reject a .ele whose triangles are each counter-clockwise but overlap
# (here two that cross without sharing an edge), or meet other than at shared corners (a corner
# on another triangle's edge), with an error naming the .ele, exit 1 and no output files. A
# correct mesh (two triangles sharing an edge) is still accepted.
#   rebuild-overlap.sh DELTRI
set -u
deltri=$1
work=$(mktemp -d) || exit 1
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
fail=0
expect_error() {  # base
  "$deltri" -rC "$1" >/dev/null 2>stderr
  status=$?
  echo "$1: exit $status: $(head -n 1 stderr)"
  [ $status -eq 1 ] || { echo "FAIL: $1 should be rejected"; fail=1; }
  head -n 1 stderr | grep -q "^$1.ele: triangle" || { echo "FAIL: $1: not an error about $1.ele"; fail=1; }
  ! ls "$1".1.* >/dev/null 2>&1 || { echo "FAIL: $1: output written"; fail=1; }
}
printf '6 2 0 0\n1 0 0\n2 1 0\n3 0 1\n4 0.2 0.2\n5 1.2 0.2\n6 0.2 1.2\n' > crossing.node
printf '2 3 0\n1 1 2 3\n2 4 5 6\n' > crossing.ele
expect_error crossing
# The same two triangles refined: -q must not start from them either.
"$deltri" -rq33a0.001C crossing >/dev/null 2>&1 && { echo "FAIL: -rq accepted the crossing pair"; fail=1; }
# A small triangle lying inside a large one, sharing no vertex.
printf '6 2 0 0\n1 0 0\n2 4 0\n3 0 4\n4 1 1\n5 2 1\n6 1 2\n' > nested.node
printf '2 3 0\n1 1 2 3\n2 4 5 6\n' > nested.ele
expect_error nested
# A T-junction: vertex 4 = (1, 0) is a corner of triangle 2 and lies on the edge 1-2 of triangle 1.
printf '5 2 0 0\n1 0 0\n2 2 0\n3 1 1\n4 1 0\n5 2 -1\n' > tee.node
printf '2 3 0\n1 1 2 3\n2 4 5 2\n' > tee.ele
expect_error tee
# Sound: the unit square as two triangles.
printf '4 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n' > square.node
printf '2 3 0\n1 1 2 3\n2 1 3 4\n' > square.ele
"$deltri" -rQC square || { echo "FAIL: a sound mesh was rejected"; fail=1; }
[ $fail -eq 0 ] && echo ok
exit $fail
