#!/bin/sh
# Issue 17 item 7: true messages for empty results.
# - -r with a .ele of 0 triangles over a square and its centre: not "collinear or fewer than
#   three distinct" (false), but that the .ele lists no triangles.
# - vertices that are all one point (or two) once duplicates are merged: the error of a header
#   with fewer than three vertices (exit 1, no files), not an empty mesh with exit 0.
#   empty-messages.sh DELTRI
set -u
deltri=$1
work=$(mktemp -d) || exit 1
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
fail=0
printf '5 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n5 0.5 0.5\n' > square.node
printf '0 3 0\n' > square.ele
"$deltri" -rQ square 2>stderr
status=$?
echo "-r with 0 triangles: exit $status: $(cat stderr)"
grep -q "collinear" stderr && { echo "FAIL: the square and its centre are not collinear"; fail=1; }
grep -q "lists no triangles" stderr || { echo "FAIL: no true message"; fail=1; }
for input in "3 1 1 1" "4 1 1 2 2"; do  # vertex count, then the x coordinates (y = x)
  set -- $input
  n=$1; shift
  { echo "$n 2 0 0"; i=0; for x in "$@"; do i=$((i + 1)); echo "$i $x $x"; done; } > same.node
  "$deltri" same.node >/dev/null 2>stderr
  status=$?
  echo "$n vertices, all duplicates of $(echo "$@" | tr ' ' '\n' | sort -u | wc -l) points: exit $status: $(head -n 1 stderr)"
  [ $status -eq 1 ] || { echo "FAIL: should be an input error"; fail=1; }
  head -n 1 stderr | grep -q "^same.node: a triangulation needs at least 3 distinct vertices" || { echo "FAIL: wrong message"; fail=1; }
  ! ls same.1.* >/dev/null 2>&1 || { echo "FAIL: output written"; fail=1; }
  rm -f same.1.*
done
[ $fail -eq 0 ] && echo ok
exit $fail
