#!/bin/sh
# The memory budget is asked only once a run grows (termination_guard.h, kProbeAfterSteiner: a
# small run asks nothing, cli.small_run_syscalls), and then caps it as before: a rectangle 1 x 1e-6
# at -pq30 (four vertices; two million triangles if nothing stops it) under `ulimit -v 400000`
# (KiB) exits 0 with the warning that the cap from the memory available stopped it, and has at
# most budget / 256 Steiner points (kBytesPerSteiner), each node a line of the .node file. Skipped
# (77) under AddressSanitizer, which cannot start under ulimit -v.
# usage: memory_probe.sh DELTRI
deltri=$1
if grep -q __asan_init "$deltri" 2>/dev/null; then echo "memory_probe: AddressSanitizer build, skipped"; exit 77; fi
work=$(mktemp -d "${TMPDIR:-/tmp}/deltri-memory-probe.XXXXXX") || exit 2
trap 'rm -rf "$work"' EXIT
fail() { echo "memory_probe: $*" >&2; cat "$work/stderr" >&2; exit 1; }
printf '4 2 0 0\n1 0 0\n2 1 0\n3 1 0.000001\n4 0 0.000001\n4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n0\n' >"$work/thin.poly"
(ulimit -v 400000 && exec "$deltri" --threads=1 -pq30Q "$work/thin.poly") 2>"$work/stderr"
status=$?
[ $status -eq 0 ] || fail "exit $status"
grep -q 'cap from the memory available' "$work/stderr" || fail "no warning that the memory cap stopped refinement"
nodes=$(head -n 1 "$work/thin.1.node" | awk '{print $1}')
[ -n "$nodes" ] || fail "no .node file"
[ "$nodes" -le $((400000 * 1024 / 256 + 4)) ] || fail "$nodes vertices: more than the budget holds"
[ "$(grep -c -v -e '^#' -e '^$' "$work/thin.1.node")" -eq $((nodes + 1)) ] || fail "the .node file is not whole"
echo "memory_probe: stopped at $nodes vertices by the budget asked late"
