#!/bin/sh
# Thin domains against Triangle 1.6 (issue 16: "the triangle count is within 10% of Triangle
# 1.6's"): for every row of TABLE.md (input, switches, Triangle's count) deltri meshes the input,
# deltri_mesh_verify checks the mesh with the angle bound, and the count must be at most 1.1 times
# Triangle's.
#   thin_domains.sh DELTRI VERIFY INPUT_DIR TABLE.md
set -u
deltri=$1 verify=$2 inputs=$3 table=$4
work=$(mktemp -d) || exit 1
trap 'rm -rf "$work"' EXIT
rows=$(grep -E '^\| (rect:|[^ ]+\.poly)' "$table" | tr -d '|')
[ -n "$rows" ] || { echo "FAIL: no rows in $table"; exit 1; }
failed=0
while read -r input switches reference; do
  rm -rf "$work/run" && mkdir "$work/run"
  case $input in
    rect:*)
      h=${input#rect:} file=rect.poly
      printf '4 2 0 0\n1 0 0\n2 1 0\n3 1 %s\n4 0 %s\n4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n0\n' "$h" "$h" >"$work/run/$file" ;;
    *) file=$input && cp "$inputs/$file" "$work/run/" ;;
  esac
  angle=${switches#-pq}
  if ! (cd "$work/run" && "$deltri" "${switches}Q" "$file" 2>"$work/err"); then
    echo "FAIL: deltri $switches $input: $(head -1 "$work/err")"; failed=1; continue
  fi
  [ -s "$work/err" ] && { echo "FAIL: deltri $switches $input warned: $(head -1 "$work/err")"; failed=1; }
  base=$work/run/${file%.poly}.1
  n=$(head -1 "$base.ele" | awk '{ print $1 }')
  if ! "$verify" --refined --min-angle "$angle" --input "$work/run/$file" --mesh "$base" >"$work/verify" 2>&1; then
    echo "FAIL: $input $switches: $(head -3 "$work/verify")"; failed=1
  fi
  if [ $((n * 10)) -gt $((reference * 11)) ]; then
    echo "FAIL: $input $switches: $n triangles, more than 1.1 x Triangle's $reference"; failed=1
  else
    echo "$input $switches: $n triangles (Triangle 1.6: $reference)"
  fi
done <<ROWS
$rows
ROWS
[ $failed = 0 ] && echo ok
exit $failed
