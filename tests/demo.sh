#!/bin/sh
# make demo: deltri's real job on every sample in data/, in a scratch folder (build/demo/):
#   demo.sh DELTRI DATA_DIR [OUT_DIR]
# Quality meshing with no angle below 30 degrees (-pq30 for a .poly, -q30 for a .node, which is
# meshed inside its convex hull), plus an area bound for the samples that are otherwise only a
# handful of triangles; -C checks every mesh exactly. One table row per file: triangles, smallest
# angle, and a note only where there is something to say. Warnings about repaired input are kept
# in NAME.log next to the outputs, and a row names the log only when it has something in it.
exe=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
data=$2
out=${3:-build/demo}
mkdir -p "$out" || exit 1
status=0
count=0
started=$(date +%s)

# An area bound (about 1/300 of the bounding box) for the samples that are a few triangles without.
area_bound() {
  case $1 in
    box.poly) echo a0.03 ;;
    square_with_crack.poly) echo a0.003 ;;
    overlapping_constraints.poly) echo a0.1 ;;
    issue-42-hole-overlaps-bondary.poly) echo a0.02 ;;
    robustness4.node) echo a0.15 ;;
  esac
}

# Samples whose segments enclose no region: with -p alone every triangle is outside them and the
# mesh is empty, in Triangle too; -c keeps the convex hull so that there is a mesh to show.
hull() {
  case $1 in
    corner_cases.poly | crossing-edges.poly) echo c ;;
  esac
}

# A JSON report's number field (the first one of that name).
field() { sed -n "s/.*\"$2\":\([0-9.e+-]*\).*/\1/p" "$1" | head -n 1; }

# What the row says about triangles below the angle bound: how many, and why, from the report's
# causes (input angles: between input segments, which refinement keeps, as Triangle does).
misses_note() {
  missing=$(field "$1" triangles_missing_bounds)
  [ "${missing:-0}" = 0 ] && return
  why=""
  for cause in small_input_angle:"input angles" repaired_crossing_or_overlap:"repaired crossings" \
               double_precision:"double precision" steiner_limits:"Steiner limits" other:other; do
    n=$(field "$1" "${cause%%:*}")
    [ "${n:-0}" != 0 ] && why="${why:+$why, }$n ${cause#*:}"
  done
  crossings=$(field "$1" triangles_missing_bounds_at_input_crossings)
  [ "${crossings:-0}" != 0 ] && why="$why ($crossings of them at crossings of input segments)"
  echo "$missing < 30: $why"
}

printf '%-36s %-15s %9s %9s  %s\n' sample switches triangles "min angle" "note (angles in degrees)"
for f in "$data"/*.poly "$data"/*.node; do
  [ -f "$f" ] || continue
  cp "$f" "$out/"
  name=$(basename "$f")
  base=${name%.*}
  case "$name" in
    *.poly) switches=-pq30$(area_bound "$name")$(hull "$name")C ;;
    *) switches=-q30$(area_bound "$name")C ;;
  esac
  log=$out/$base.log
  if (cd "$out" && "$exe" "$switches" --svg --json "$name" >/dev/null 2>"$base.log"); then
    report=$out/$base.1.json
    triangles=$(sed -n 's/.*"mesh":{[^}]*"triangles":\([0-9]*\).*/\1/p' "$report")
    angle=$(sed -n 's/.*"quality":{[^}]*"smallest_angle":\([^,]*\),.*/\1/p' "$report")
    notes=""
    [ -n "$(hull "$name")" ] && notes="-c: no closed region (empty with -p alone)"
    if [ "$triangles" = 0 ]; then
      reason=$(grep -m 1 -E 'the mesh is empty|no triangles' "$log" | sed 's/^deltri: warning: [^:]*: //')
      notes="${reason:-empty mesh}"
      angle=-
    else
      angle=$(printf '%.3g' "$angle")
      m=$(misses_note "$report")
      [ -n "$m" ] && notes="${notes:+$notes; }$m"
    fi
    warnings=$(grep -c "warning" "$log")
    if [ "$warnings" -gt 0 ]; then
      notes="${notes:+$notes; }$warnings warning$([ "$warnings" -gt 1 ] && echo s): $base.log"
    elif [ ! -s "$log" ]; then
      rm -f "$log"  # nothing to read there
    fi
    printf '%-36s %-15s %9s %9s  %s\n' "$name" "$switches" "$triangles" "$angle" "$notes"
    count=$((count + 1))
  else
    echo "demo: $name failed:" >&2
    cat "$log" >&2
    status=1
  fi
done
echo "demo: $count meshes, each checked by -C, in $(($(date +%s) - started)) s; pictures (NAME.1.svg), meshes and JSON reports in $out"
exit $status
