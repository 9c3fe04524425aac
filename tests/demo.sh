#!/bin/sh
# make demo: mesh every sample file in data/ in a scratch directory and print one summary line per
# file. Every mesh is checked by deltri's exact consistency check (-C); warnings about repaired
# input are kept in NAME.log next to the outputs and counted on the line.
exe=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
data=$2
out=${3:-build/demo}
mkdir -p "$out"
status=0
for f in "$data"/*.poly "$data"/*.node; do
  [ -f "$f" ] || continue
  cp "$f" "$out/"
  name=$(basename "$f")
  case "$name" in
    *.poly) switches=${DEMO_POLY_SWITCHES:--pC} ;;
    *) switches=${DEMO_NODE_SWITCHES:--C} ;;
  esac
  if summary=$(cd "$out" && "$exe" "$switches" "$name" 2>"$name.log"); then
    warnings=$(grep -c "warning" "$out/$name.log")
    if [ "$warnings" -eq 1 ]; then
      echo "$summary [1 warning: $out/$name.log]"
    elif [ "$warnings" -gt 1 ]; then
      echo "$summary [$warnings warnings: $out/$name.log]"
    else
      echo "$summary"
    fi
  else
    echo "demo: $name failed:" >&2
    cat "$out/$name.log" >&2
    status=1
  fi
done
exit $status
