#!/bin/sh
# Corpus sweep (not a CTest: the corpus is not part of the repository). Runs deltri with -C on
# every .node and .poly under CORPUS, for each switch set in SWEEP_SWITCHES (default
# "-p -pq30 -pq33"; an `A` in a switch set is replaced by the input's bounding-box area / 25000 to
# two significant digits, the area of triangle-reference-counts.md), with a time limit. Then it
# checks every mesh it wrote with tests/tools' verifier (-p only: refined meshes have rounded
# points on segments, which that verifier rejects by design) and, when MESHCHECK names it and the
# mesh has at most SWEEP_MESHCHECK_MAX triangles (default 60000), with the independent
# meshcheck.py, given --min-angle Q for -qQ and --max-area A for -aA. Prints one Markdown table
# row per run.
# SWEEP_EXTRA is passed to every run as well (say, --queue=edge).
#   [SWEEP_SWITCHES="-pq20 -pq30 -pq33 -pq30aA"] sweep.sh BUILD_DIR CORPUS [MESHCHECK]
set -u
build=$1 corpus=$2 meshcheck=${3:-}
# The runs happen in a scratch directory: make the checker's path absolute.
case $meshcheck in '' | /*) ;; *) meshcheck=$(pwd)/$meshcheck ;; esac
deltri=$build/deltri verify=$build/tests/deltri_mesh_verify
switch_sets=${SWEEP_SWITCHES:--p -pq30 -pq33}
max_checked=${SWEEP_MESHCHECK_MAX:-60000}
extra=${SWEEP_EXTRA:-}
work=$(mktemp -d) || exit 1
trap 'rm -rf "$work"' EXIT

# The bounding-box area / 25000 of the vertices of a .node file (or of the .poly's own vertices).
area_of() {
  awk '/^[[:space:]]*#/ || NF == 0 { next }
       !n { n = $1; next }
       seen < n { x = $2 + 0; y = $3 + 0
                  if (!seen || x < x0) x0 = x; if (!seen || x > x1) x1 = x
                  if (!seen || y < y0) y0 = y; if (!seen || y > y1) y1 = y; seen++ }
       END { if (seen) printf "%.2g\n", (x1 - x0) * (y1 - y0) / 25000 }' "$1" |
    awk '{ v = $1 + 0; s = sprintf("%.12f", v); sub(/0+$/, "", s); sub(/\.$/, "", s); print s }'
}

echo "| file | switches | exit | seconds | triangles | verifier | meshcheck | first message |"
echo "|---|---|---|---|---|---|---|---|"
find "$corpus" -name '*.poly' -o -name '*.node' | LC_ALL=C sort | while read -r f; do
  rel=${f#"$corpus"/}
  limit=60
  case $rel in VVingerfly__Triangulation/test.poly) limit=600 ;; esac
  src=$f
  case $f in *.poly) [ -f "${f%.*}.node" ] && [ "$(awk '!/^#/ && NF { print $1; exit }' "$f")" = 0 ] && src=${f%.*}.node ;; esac
  area=$(area_of "$src")
  for set in $switch_sets; do
    sw=$(echo "$set" | sed "s/A\$/$area/")
    rm -rf "$work/run" && mkdir "$work/run"
    # A .poly with zero vertices reads the .node beside it.
    cp "$f" "$work/run/" && { [ -f "${f%.*}.node" ] && cp "${f%.*}.node" "$work/run/" 2>/dev/null; true; }
    name=$(basename "$f") base=${name%.*}
    # Output names count the iteration on: box.1.poly gives box.2.*, box.poly box.1.*.
    out=$(echo "$base" | awk -F. 'NF > 1 && $NF ~ /^[0-9]+$/ { $NF = $NF + 1; OFS = "."; $1 = $1; print; next } { print $0 ".1" }')
    start=$(date +%s.%N)
    (cd "$work/run" && timeout "$limit" "$deltri" "$sw"CQ $extra "$name" >/dev/null 2>"$work/err")
    status=$?
    seconds=$(echo "$start $(date +%s.%N)" | awk '{ printf "%.2f", $2 - $1 }')
    [ $status = 124 ] && status="TIMEOUT ($limit s)"
    tri=- v=- m=-
    if [ -f "$work/run/$out.ele" ]; then
      tri=$(awk '!/^#/ && NF { print $1; exit }' "$work/run/$out.ele")
      if [ "$sw" = -p ]; then
        case $name in *.node) vopt=--convex-hull ;; *) vopt= ;; esac
        (cd "$work/run" && "$verify" --input "$name" --mesh "$out" $vopt >/dev/null 2>&1) && v=ok || v=FAIL
      fi
      if [ -n "$meshcheck" ] && [ "$tri" -le "$max_checked" ]; then
        case $name in *.node) mopt=--convex-hull ;; *) mopt= ;; esac
        q=$(echo "$sw" | sed -n 's/^-[^q]*q\([0-9.]*\).*/\1/p')
        a=$(echo "$sw" | sed -n 's/^-[^a]*a\([0-9.]*\).*/\1/p')
        [ -n "$q" ] && mopt="$mopt --min-angle $q"
        [ -n "$a" ] && mopt="$mopt --max-area $a"
        (cd "$work/run" && timeout 600 python3 "$meshcheck" --input "$name" --mesh "$out" $mopt >"$work/mc" 2>&1)
        case $? in 0) m=ok ;; 124) m=timeout ;; *) m="FAIL: $(grep -m1 -i -E 'fail|unexplained' "$work/mc" | sed 's/|/\\|/g' | cut -c1-80)" ;; esac
      fi
    fi
    msg=$(grep -v '^$' "$work/err" | head -n 1 | sed 's/|/\\|/g' | cut -c1-110)
    echo "| $rel | $sw | $status | $seconds | $tri | $v | $m | $msg |"
  done
done
