#!/bin/sh
# --threads=1 means one thread (issue 24): reading, the Delaunay build, refinement in parts, the
# counts after it and the writers all stay on the calling thread. thread_probe (preloaded) notes
# every thread started; with --threads=1 there must be none, with --threads=2 some, which shows
# that the probe sees them. Inputs large enough for every parallel path: a 300,000-point .node
# (read in halves, a split build, ranged writers) and the 30x30 holes at -pq30 (2 parts), then
# refined again from its .ele with -r.
# usage: one_thread.sh DELTRI BENCH_GEN PROBE
deltri=$1 gen=$2 probe=$3
work=$(mktemp -d "${TMPDIR:-/tmp}/deltri-one-thread.XXXXXX") || exit 2
trap 'rm -rf "$work"' EXIT
fail() { echo "one_thread: $*" >&2; exit 1; }
"$gen" uniform 300000 "$work/pts.node" >/dev/null && "$gen" holes 30 "$work/holes.poly" >/dev/null || fail "the generator failed"
started() {  # threads: command...; prints how many threads the run started
  t=$1; shift
  LD_PRELOAD="$probe" "$deltri" -Q --threads=$t "$@" 2>"$work/err.txt" || { cat "$work/err.txt" >&2; fail "deltri $* failed"; }
  grep -c "thread_probe: a thread was started" "$work/err.txt" || true  # 0 lines: status 1
}
for t in 2 1; do
  points=$(started $t "$work/pts.node") && holes=$(started $t -pq30 "$work/holes.poly") &&
    again=$(started $t -rpq33 "$work/holes.1") || exit 1
  echo "--threads=$t: $points threads for the points, $holes for the holes, $again for -r"
  if [ $t = 2 ]; then
    [ "$points" -gt 0 ] && [ "$holes" -gt 0 ] || fail "the probe saw no thread at --threads=2"
  else
    [ "$points" = 0 ] && [ "$holes" = 0 ] && [ "$again" = 0 ] || fail "--threads=1 started threads"
  fi
done
# The default thread count is the affinity mask's: pinned to one core, deltri starts no thread.
if command -v taskset >/dev/null 2>&1 && taskset -c 0 true 2>/dev/null; then
  LD_PRELOAD="$probe" taskset -c 0 "$deltri" -Q "$work/pts.node" 2>"$work/err.txt" || { cat "$work/err.txt" >&2; fail "pinned deltri failed"; }
  pinned=$(grep -c "thread_probe: a thread was started" "$work/err.txt")
  echo "taskset -c 0, default threads: $pinned threads for the points"
  [ "$pinned" = 0 ] || fail "pinned to one core, the default threads started $pinned"
fi
