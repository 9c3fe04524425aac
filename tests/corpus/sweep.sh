#!/bin/sh
# Corpus sweep (not a CTest: the corpus is not part of the repository). Runs deltri with -C on
# every .node and .poly under CORPUS at -p, -pq30 and -pq33 with a time limit, then checks every
# mesh it wrote with tests/tools' verifier (-p only: refined meshes have rounded points on
# segments, which that verifier rejects by design) and, when MESHCHECK names it and the mesh has at
# most 60000 triangles, with the independent meshcheck.py. Prints one Markdown table row per run.
#   sweep.sh BUILD_DIR CORPUS [MESHCHECK]
set -u
build=$1 corpus=$2 meshcheck=${3:-}
deltri=$build/deltri verify=$build/tests/deltri_mesh_verify
work=$(mktemp -d) || exit 1
trap 'rm -rf "$work"' EXIT
echo "| file | switches | exit | seconds | triangles | verifier | meshcheck | first message |"
echo "|---|---|---|---|---|---|---|---|"
find "$corpus" -name '*.poly' -o -name '*.node' | LC_ALL=C sort | while read -r f; do
  rel=${f#"$corpus"/}
  limit=60
  case $rel in VVingerfly__Triangulation/test.poly) limit=600 ;; esac
  for sw in -p -pq30 -pq33; do
    rm -rf "$work/run" && mkdir "$work/run"
    # A .poly with zero vertices reads the .node beside it.
    cp "$f" "$work/run/" && { [ -f "${f%.*}.node" ] && cp "${f%.*}.node" "$work/run/" 2>/dev/null; true; }
    name=$(basename "$f") base=${name%.*}
    # Output names count the iteration on: box.1.poly gives box.2.*, box.poly box.1.*.
    out=$(echo "$base" | awk -F. 'NF > 1 && $NF ~ /^[0-9]+$/ { $NF = $NF + 1; OFS = "."; $1 = $1; print; next } { print $0 ".1" }')
    start=$(date +%s.%N)
    (cd "$work/run" && timeout "$limit" "$deltri" "$sw"CQ "$name" >/dev/null 2>"$work/err")
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
      if [ -n "$meshcheck" ] && [ "$tri" -le 60000 ]; then
        case $name in *.node) mopt=--convex-hull ;; *) mopt= ;; esac
        (cd "$work/run" && timeout 300 python3 "$meshcheck" --input "$name" --mesh "$out" $mopt >"$work/mc" 2>&1)
        case $? in 0) m=ok ;; 124) m=timeout ;; *) m="FAIL: $(grep -m1 -i fail "$work/mc" | cut -c1-80)" ;; esac
      fi
    fi
    msg=$(grep -v '^$' "$work/err" | head -n 1 | sed 's/|/\\|/g' | cut -c1-110)
    echo "| $rel | $sw | $status | $seconds | $tri | $v | $m | $msg |"
  done
done
