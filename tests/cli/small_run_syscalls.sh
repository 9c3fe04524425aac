#!/bin/sh
# A small run pays no fixed cost sized for large ones (issue 45): guitar.poly at -pq30 (351
# triangles), traced with strace, returns no pages with madvise (the quality queue keeps its few
# blocks), reads no core count from sysfs (the default thread count comes from the affinity mask),
# asks nothing about the machine's memory (no sysinfo, no address-space or data limit, no cgroup:
# the budget is asked only once a run grows, termination_guard.h) and starts no thread; it still
# writes its three files. Where the file system makes unnamed files (O_TMPFILE),
# each file is written unnamed and, its name being free, linked straight at its final name: no
# temporary name, no rename and no lock (one directory entry a file, as Triangle's plain create),
# none created by name with O_CREAT (an O_CREAT open makes the inode holding the directory's lock,
# so runs in one folder took turns). Exit 77 (skipped) without strace or where the kernel refuses
# tracing.
# usage: small_run_syscalls.sh DELTRI DATA_DIR
deltri=$1 data=$2
command -v strace >/dev/null 2>&1 || { echo "small_run_syscalls: no strace, skipped"; exit 77; }
work=$(mktemp -d "${TMPDIR:-/tmp}/deltri-small-syscalls.XXXXXX") || exit 2
trap 'rm -rf "$work"' EXIT
fail() { echo "small_run_syscalls: $*" >&2; cat "$work/trace.txt" >&2; exit 1; }
cp "$data/guitar.poly" "$work/" || exit 2
strace -f -o "$work/trace.txt" -e trace=madvise,openat,open,clone,clone3,linkat,rename,renameat,renameat2,flock,sysinfo,prlimit64,getrlimit "$deltri" -pq30Q "$work/guitar.poly" ||
  { [ -s "$work/trace.txt" ] || { echo "small_run_syscalls: strace cannot trace here, skipped"; exit 77; }; fail "deltri failed"; }
for f in node ele poly; do [ -s "$work/guitar.1.$f" ] || fail "guitar.1.$f was not written"; done
grep -q 'guitar.poly' "$work/trace.txt" || fail "the trace shows no open of the input: it does not see the program's calls"
! grep -q 'madvise(' "$work/trace.txt" || fail "a small run called madvise"
! grep -q '"/sys/devices/system/cpu' "$work/trace.txt" || fail "a small run read the core count from sysfs"
! grep -q 'clone' "$work/trace.txt" || fail "a small run started a thread"
! grep -q -e 'sysinfo(' -e 'RLIMIT_AS' -e 'RLIMIT_DATA' -e '/cgroup' "$work/trace.txt" || fail "a small run asked for the memory budget"
if grep -q 'O_TMPFILE.* = [0-9]' "$work/trace.txt"; then
  [ "$(grep -c 'linkat(.*"[^"]*guitar\.1\.\(node\|ele\|poly\)", .* = 0' "$work/trace.txt")" -eq 3 ] ||
    fail "the three files were not linked from unnamed files at their final names"
  ! grep -q '\.tmp\.' "$work/trace.txt" || fail "a temporary name was made where the final names were free"
  ! grep -q -e 'rename' -e 'flock(' "$work/trace.txt" || fail "a rename or a lock where the final names were free"
  ! grep -q 'guitar\.1\..*O_CREAT' "$work/trace.txt" || fail "a temporary was created by name where O_TMPFILE works"
elif ! grep -q 'O_TMPFILE' "$work/trace.txt"; then
  fail "no temporary was made unnamed (O_TMPFILE)"
fi
echo "small_run_syscalls: no madvise, no sysfs core count, no memory budget, no thread; three files linked at their names from unnamed files where the file system allows"
