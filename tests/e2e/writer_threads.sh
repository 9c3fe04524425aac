#!/bin/sh
# The .node and .ele of a point set many write ranges long (TextWriter::kItemsPerRange) are the
# same whatever --threads says, and their line numbers run 1..N without a gap or repeat: the ranges are formatted on different threads and must join seamlessly.
# usage: writer_threads.sh DELTRI BENCH_GEN
set -eu
deltri=$1
gen=$2
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
"$gen" uniform 60000 "$dir/pts.node" >/dev/null
# Consecutive indices from $2 on, as many as the header ($1 its first field) announces.
check_numbering() {
  awk -v first="$2" 'NR == 1 { n = $1; next } /^#/ { next } {
      if ($1 != first + NR - 2) { print FILENAME ": line " NR " has index " $1 ", not " first + NR - 2; bad = 1; exit }
    } END { if (!bad && NR - 1 != n) { print FILENAME ": " NR - 1 " lines, header says " n; bad = 1 }
            exit bad }' "$1"
}
first=1
for switches in -Q -Qo2 -QB; do
  for t in 1 2 3 4 8; do
    mkdir -p "$dir/t$t"
    cp "$dir/pts.node" "$dir/t$t/pts.node"
    "$deltri" $switches --threads=$t "$dir/t$t/pts.node"
    for f in pts.1.node pts.1.ele; do
      check_numbering "$dir/t$t/$f" $first
      if [ $t -ne 1 ] && ! cmp -s "$dir/t1/$f" "$dir/t$t/$f"; then
        echo "$switches: $f differs between --threads=1 and --threads=$t"
        exit 1
      fi
    done
  done
  lines=$(wc -l <"$dir/t1/pts.1.ele")
  if [ "$lines" -lt 100000 ]; then
    echo "$switches: only $lines .ele lines, fewer than several write ranges"
    exit 1
  fi
done
echo "writer_threads: identical for --threads=1..8"
