#!/bin/sh
# make fuzz: runs one libFuzzer target for a given time (one process: the machine is shared).
#   run.sh BUILD_DIR TARGET SECONDS [LIBFUZZER_FLAGS]
# TARGET is fuzz_readers, fuzz_pipeline, fuzz_library or fuzz_surface. The corpus grows in BUILD_DIR/corpus-TARGET and is
# reused by later runs; crash, timeout and leak inputs land in BUILD_DIR/findings-TARGET/.
# The seeds are the inputs in data/ and tests/e2e/inputs, each prefixed with the selector bytes
# the target reads first (see the targets' comments).
set -eu
build=$1 target=$2 seconds=$3 extra=${4:-}
root=$(cd "$(dirname "$0")/../.." && pwd)
seeds=$build/seeds-$target corpus=$build/corpus-$target findings=$build/findings-$target
mkdir -p "$seeds" "$corpus" "$findings"

byte() { printf "\\$(printf '%03o' "$1")"; }
seed() {  # seed MODE FILE
  { byte "$1"; cat "$2"; } >"$seeds/$1-$(basename "$2")"
}
inputs="$root/data/*.node $root/data/*.poly $root/tests/e2e/inputs/*"
[ "$target" = fuzz_surface ] && inputs="$root/tests/surface/inputs/*.poly $root/tests/surface/inputs/*.smesh"
printf '4 3 0\n1 1 2 3\n2 2 3 4\n3 1 3 4\n4 1 4 5\n' >"$build/small.ele"
printf '3\n1 0.5\n2 -1\n3 1e-3\n' >"$build/small.area"
for f in $inputs "$build/small.ele" "$build/small.area"; do
  # Large seeds (debug2.poly, 400 kB) take seconds per run and starve the search.
  [ "$(wc -c <"$f")" -gt 200000 ] && continue
  case $target:$f in
    fuzz_readers:*.node) seed 0 "$f" ;;
    fuzz_readers:*.poly) seed 1 "$f" ;;
    fuzz_readers:*.ele) seed 18 "$f"; seed 22 "$f" ;;
    fuzz_readers:*.area) seed 3 "$f"; seed 27 "$f" ;;
    fuzz_pipeline:*.poly) for m in 0 2 4 16 18 20; do seed $m "$f"; done ;;
    fuzz_pipeline:*.node) for m in 1 3 5 17 19 21; do seed $m "$f"; done ;;
    fuzz_surface:*.poly) for m in 0 2 4 6; do seed $m "$f"; done ;;
    fuzz_surface:*.smesh) for m in 1 3 5 7; do seed $m "$f"; done ;;
  esac
done

# fuzz_library reads no file: its seeds are a few calls written out byte by byte (see its layout):
# "pq30" on a unit square with a hole, and "p" on a segment crossing a triangle, plus -r of 1 triangle.
if [ "$target" = fuzz_library ]; then
  printf '\004pq30\004\000\004\001\000\000\000dfhdhffff\001\002\002\003\003\004\004\001e' >"$seeds/square-hole"
  printf '\001p\004\000\002\000\000\000\003dddfffdhh\002\003\004\005' >"$seeds/crossing"
  printf '\001r\003\000\000\000\000\001\010dddffd\003\004\005f' >"$seeds/refine"
fi

cd "$findings"
exec "$build/tests/fuzz/$target" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=4096 \
  -close_fd_mask=3 -print_final_stats=1 -artifact_prefix="$findings/" $extra "$corpus" "$seeds"
