#!/bin/sh
# One regression input (called by CTest, see CMakeLists.txt in this directory):
#   run.sh DELTRI VERIFY INPUT EXPECTED
# The input's first line is "# deltri SWITCHES". EXPECTED (expected.txt) gives the outcome due:
# "mesh": deltri succeeds with -C and gives a mesh that passes deltri_mesh_verify; "error REGEX":
# it fails cleanly (exit 1, first line of stderr "NAME:LINE: message" or "NAME: message" with the
# message matching REGEX, no output file). Anything else (the other outcome, a crash, exit 3, 5
# or 6, a hang up to CTest's timeout, an input missing from EXPECTED) fails the test. An input whose second line is "# check: exact" is also checked,
# on success, by tests/tools/exact_delaunay_check.py (exact rationals, none of deltri's predicates);
# with "# check: exact only", by that checker alone.
set -u
deltri=$1 verify=$2 input=$3 expected=$4
name=$(basename "$input") base=${name%.*}
outcome=$(awk -v n="$name" '$1 == n { sub(/[ \t]+#.*$/, ""); $1 = ""; sub(/^ /, ""); print; exit }' "$expected")
case $outcome in
  mesh) want_status=0 ;;
  "error "?*) want_status=1 pattern=${outcome#error } ;;
  *) echo "FAIL: $name has no expected outcome ('mesh' or 'error REGEX') in $expected"; exit 1 ;;
esac
switches=$(sed -n '1s/^# deltri //p' "$input")
[ -n "$switches" ] || { echo "FAIL: $name lacks a '# deltri SWITCHES' first line"; exit 1; }
work=$(mktemp -d) || exit 1
trap 'rm -rf "$work"' EXIT
cp "$input" "$work/"
(cd "$work" && "$deltri" $switches -C "$name" >/dev/null 2>stderr)
status=$?
echo "deltri $switches -C $name: exit $status"
sed 's/^/  stderr: /' "$work/stderr"
echo "expected: $outcome"
[ "$status" = "$want_status" ] || [ "$status" != 0 -a "$status" != 1 ] ||
  { echo "FAIL: exit $status where the outcome due is '$outcome'"; exit 1; }
case $status in
  0)
    case $switches in *q*|*a*|*u*) refined=--refined ;; *) refined= ;; esac
    # The convex hull bounds the mesh of a .node, and with -c (the first single-dash word).
    triangle_switches=$(printf '%s\n' $switches | grep -m 1 '^-[^-]')
    case $name:$triangle_switches in *.node:* | *:*c*) hull=--convex-hull ;; *) hull= ;; esac
    # "# check: exact only": segments spanning hundreds of orders of magnitude, which the
    # verifier's long double parametrisation of a segment cannot order; the exact checker can.
    if ! sed -n 2p "$input" | grep -q '^# check: exact only'; then
      (cd "$work" && "$verify" --input "$name" --mesh "$base.1" $refined $hull) || { echo "FAIL: invalid mesh"; exit 1; }
    fi
    if sed -n 2p "$input" | grep -q '^# check: exact'; then
      case $name in *.node) exact_hull="--convex-hull $work/$name" ;; *) exact_hull= ;; esac
      /usr/bin/python3 "$(dirname "$0")/../tools/exact_delaunay_check.py" "$work/$base.1" $exact_hull ||
        { echo "FAIL: the exact checker rejects the mesh"; exit 1; }
    fi ;;
  1)
    [ -z "$(cd "$work" && ls | grep -v -x -F -e "$name" -e stderr)" ] || { echo "FAIL: output files left"; exit 1; }
    head -n 1 "$work/stderr" | grep -q "^$name:\([0-9][0-9]*:\)\{0,1\} " || { echo "FAIL: not a 'file:line: message' error"; exit 1; }
    head -n 1 "$work/stderr" | sed "s/^$name:\([0-9][0-9]*:\)\{0,1\} //" | grep -q -E -- "$pattern" ||
      { echo "FAIL: the error does not match /$pattern/"; exit 1; } ;;
  *) echo "FAIL: exit status $status"; exit 1 ;;
esac
exit 0
