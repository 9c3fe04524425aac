#!/bin/sh
# make demo: mesh every sample file in data/ into a scratch directory, one summary line per file,
# and check each result with deltri's own consistency check (-C).
set -e
exe=$1
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
  if ! "$exe" "$switches" "$out/$name"; then
    echo "demo: $name failed" >&2
    status=1
  fi
done
exit $status
