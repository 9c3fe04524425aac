#!/bin/sh
# Refinement in parts (refine/refine_in_parts.h) gives the same files for every thread count (issue 24):
# the 50x50 holes at -pq30 (165,002 initial triangles: 4 parts) with --threads=1, 2, 3, 4, 8 and 16
# (oversubscribed on a small machine, which is fine), byte for byte, the N=1 mesh checked by -C and
# by the independent checker of the end-to-end tests, and -V saying that it was cut into 4 parts.
# usage: parts_threads.sh DELTRI BENCH_GEN MESH_VERIFY [HOLES]
deltri=$1 gen=$2 verify=$3 holes=${4:-50}
work=$(mktemp -d "${TMPDIR:-/tmp}/deltri-parts.XXXXXX") || exit 2
trap 'rm -rf "$work"' EXIT
fail() { echo "parts_threads: $*"; exit 1; }
"$gen" holes "$holes" "$work/holes.poly" || fail "the generator failed"
for n in 1 2 3 4 8 16; do
  mkdir "$work/t$n" && cp "$work/holes.poly" "$work/t$n/" || exit 2
  check=; [ $n = 1 ] && check=C
  (cd "$work/t$n" && "$deltri" -pq30V$check --threads=$n holes.poly >out.txt 2>err.txt) || { cat "$work/t$n/err.txt"; fail "--threads=$n failed"; }
done
grep -q "refined in 4 parts apart" "$work/t1/out.txt" || fail "not cut into 4 parts: $(grep 'refined in' "$work/t1/out.txt")"
grep -q "Mesh is consistent" "$work/t1/out.txt" || fail "-C did not pass"
for n in 2 3 4 8 16; do
  for f in holes.1.node holes.1.ele holes.1.poly; do
    cmp -s "$work/t1/$f" "$work/t$n/$f" || fail "$f differs between --threads=1 and --threads=$n"
  done
done
(cd "$work/t1" && "$verify" --input holes.poly --mesh holes.1 --refined --min-angle 30) || fail "deltri_mesh_verify found faults"
echo "the same files for --threads=1, 2, 3, 4, 8 and 16 ($(grep 'refined in' "$work/t1/out.txt" | sed 's/^ *//'))"
