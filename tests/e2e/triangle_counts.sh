#!/bin/sh
# Refinement against Triangle 1.6 on the samples in data/ (issue: "Triangle counts no more than
# Triangle 1.6's for the same switches, summed"):
#   triangle_counts.sh DELTRI VERIFY DATA_DIR TABLE.md
# For every row of TABLE.md (file, A, Triangle's counts at -pq30, -pq33, -pq30aA) deltri runs with
# those switches; every mesh must pass deltri_mesh_verify with the angle bound (and the area bound
# for -pq30aA), and for each of the three switch strings the sum of deltri's triangle counts must
# not exceed the sum of Triangle's. Prints one line per file and the sums.
set -u
deltri=$1 verify=$2 data=$3 table=$4
work=$(mktemp -d) || exit 1
trap 'rm -rf "$work"' EXIT
failed=0 ours30=0 ours33=0 oursA=0 ref30=0 ref33=0 refA=0
rows=$(grep -E '^\| [^ ]+\.poly \|' "$table" | tr -d '|')
[ -n "$rows" ] || { echo "FAIL: no rows in $table"; exit 1; }
printf '%s\n' "$rows" | {
  while read -r file area t30 t33 tA; do
    line="$file:"
    for mode in q30 q33 q30a; do
      case $mode in
        q30) sw=-pq30 checks="--min-angle 30" ;;
        q33) sw=-pq33 checks="--min-angle 33" ;;
        q30a) sw=-pq30a$area checks="--min-angle 30 --max-area $area" ;;
      esac
      rm -rf "$work/run" && mkdir "$work/run" && cp "$data/$file" "$work/run/"
      base=${file%.poly}
      if ! (cd "$work/run" && "$deltri" "${sw}Q" "$file" 2>"$work/err"); then
        echo "FAIL: deltri $sw $file: $(head -1 "$work/err")"; failed=1; continue
      fi
      n=$(head -1 "$work/run/$base.1.ele" | awk '{ print $1 }')
      # shellcheck disable=SC2086
      if ! "$verify" --input "$work/run/$file" --mesh "$work/run/$base.1" --refined $checks >"$work/verify"; then
        echo "FAIL: $file $sw: $(head -3 "$work/verify")"; failed=1
      fi
      case $mode in
        q30) ours30=$((ours30 + n)) ref30=$((ref30 + t30)) ref=$t30 ;;
        q33) ours33=$((ours33 + n)) ref33=$((ref33 + t33)) ref=$t33 ;;
        q30a) oursA=$((oursA + n)) refA=$((refA + tA)) ref=$tA ;;
      esac
      line="$line $sw $n (Triangle $ref)"
    done
    echo "$line"
  done
  echo "sum -pq30: deltri $ours30, Triangle $ref30"
  echo "sum -pq33: deltri $ours33, Triangle $ref33"
  echo "sum -pq30a: deltri $oursA, Triangle $refA"
  [ "$ours30" -le "$ref30" ] || { echo "FAIL: more triangles than Triangle at -pq30"; failed=1; }
  [ "$ours33" -le "$ref33" ] || { echo "FAIL: more triangles than Triangle at -pq33"; failed=1; }
  [ "$oursA" -le "$refA" ] || { echo "FAIL: more triangles than Triangle at -pq30a"; failed=1; }
  exit $failed
}
