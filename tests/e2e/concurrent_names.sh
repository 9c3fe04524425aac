#!/bin/sh
# Concurrent runs in one folder (issue 45): runs writing other output names never wait for each
# other and never warn; two runs writing the same names still leave one run's complete set, never
# a mix. Made certain rather than left to a race: run A is stopped between two of its renames (a
# preloaded hook, rename_hook.c, stops it right after its first rename, holding its locks, or
# right after it linked its first file at its final name, where no output was there before), and
# run B goes ahead meanwhile.
#   concurrent_names.sh DELTRI RENAME_HOOK DATA_DIR
# (PATIENCE in the environment: how long B may take before A is let go anyway, 120 s; it only
# bounds how long a failing test takes.)
set -u
deltri=$1 hook=$2 data=$3 patience=${PATIENCE:-120}
work=$(mktemp -d) || exit 1
trap 'kill -CONT $a 2>/dev/null; rm -rf "$work"' EXIT
a=
cd "$work" || exit 1
LD_PRELOAD=$hook "$deltri" --version >/dev/null 2>&1 || { echo "skipped: the hook cannot be preloaded here"; exit 77; }
failed=0
fail() { echo "FAIL: $*"; failed=1; }
# set_of STEM NAME...: the NAME whose .node, .ele and .poly STEM.1.* equal byte for byte, or "mixed".
set_of() {
  stem=$1
  shift
  for name in "$@"; do
    same=1
    for ext in node ele poly; do cmp -s $stem.1.$ext $name.$ext || same=0; done
    [ $same = 1 ] && { echo $name; return; }
  done
  echo mixed
}
cp "$data/guitar.poly" a.poly
cp "$data/guitar.poly" b.poly
cp "$data/box.poly" small.poly
# Reference sets, one run after the other: a .poly of guitar and of box written as one name.
"$deltri" -pq30Q guitar.poly 2>/dev/null || cp a.poly guitar.poly
"$deltri" -pq30Q a.poly && for ext in node ele poly; do mv a.1.$ext big.$ext; done
"$deltri" -pq30Q small.poly && for ext in node ele poly; do mv small.1.$ext little.$ext; done
# start_a SWITCHES INPUT: run A in the background, stopped after its first rename (returns then).
start_a() {
  rm -f mark
  DELTRI_TEST_RENAME_HOOK=stop DELTRI_TEST_RENAME_MARK=mark LD_PRELOAD=$hook "$deltri" --threads=1 "$@" 2>err.a &
  a=$!
  i=0
  while [ ! -e mark ] && [ $i -lt 6000 ] && kill -0 $a 2>/dev/null; do sleep 0.1; i=$((i + 1)); done
  [ -e mark ] || { echo "FAIL: run A never reached its renames"; exit 1; }
}
# wait_b PID: waits until B ends, or waits for a lock (a "->" line of /proc/locks), or PATIENCE
# seconds pass; then A goes on and both are waited for.
wait_b() {
  i=0
  while kill -0 "$1" 2>/dev/null && [ $i -lt $((patience * 10)) ]; do
    grep -q -e "-> *FLOCK *ADVISORY *WRITE *$1 " /proc/locks 2>/dev/null && { echo "run B waits for a lock"; break; }
    sleep 0.1
    i=$((i + 1))
  done
  [ $i -lt $((patience * 10)) ] || echo "run B has not ended after $patience s: letting A go on"
  kill -CONT $a
  wait $a; status_a=$?
  wait "$1"; status_b=$?
}

# 1. Other names: A writes a.1.*, B writes b.1.* in the same folder while A holds its locks.
start_a -pq30Q a.poly
"$deltri" -pq30Q b.poly 2>err.b &
b=$!
wait_b $b
echo "other names: A exit $status_a, B exit $status_b; B said: $(cat err.b)"
[ $status_a = 0 ] && [ $status_b = 0 ] || fail "other names: exit $status_a and $status_b"
[ -s err.a ] && fail "other names: run A warned: $(cat err.a)"
[ -s err.b ] && fail "other names: run B warned (it waited for A): $(cat err.b)"
for f in a.1.node a.1.ele a.1.poly b.1.node b.1.ele b.1.poly; do [ -s $f ] || fail "other names: $f missing"; done

# 2. The same names: both write out.1.* (a copy race: out.poly is guitar for A, then box for B,
# which reads it while A is stopped), so that a mix would pair a .node of one mesh with an .ele
# of the other. The result must be one complete set, byte for byte. Round "fresh": no out.1.*
# before; A has linked out.1.ele from an unnamed file and holds no lock, so B (finding a file
# there) goes by temporaries and ends first; A then finds out.1.node taken and puts its whole set
# in place again: A's set, and A says it met another run. Rounds 1 and 2: A's files of the round
# before are there, A goes by temporaries and holds them; B waits, and its set is left.
for round in fresh 1 2; do
  [ $round = fresh ] && rm -f out.1.*
  cp a.poly out.poly
  start_a -pq30Q out.poly
  cp small.poly out.poly
  "$deltri" -pq30Q out.poly 2>err.b &
  b=$!
  wait_b $b
  set_is=$(set_of out big little)
  echo "same names, round $round: A exit $status_a, B exit $status_b, outputs: $set_is; B said: $(cat err.b)"
  [ $status_a = 0 ] && [ $status_b = 0 ] || fail "same names: exit $status_a and $status_b"
  last=b set_last=little
  [ $round = fresh ] && last=a set_last=big
  [ $set_is = $set_last ] || fail "same names, round $round: the outputs are '$set_is', not run $last's complete set ($last ended last)"
  grep -q "warning: \(waited for another deltri run writing the same output files\|.*changed on disk\)" err.$last ||
    fail "same names, round $round: run $last did not say it met another run"
done
# 3. Started together with no hook, as a batch starts them (issue 45), PAIRS times each (20): two
# runs on different files of the folder both exit 0, say nothing and write what a run alone writes;
# two runs on the same names (-pQ against -pq30Q of one input, so that every file differs between
# the two) both exit 0 and leave one run's complete set, byte for byte.
"$deltri" -pQ a.poly && for ext in node ele poly; do mv a.1.$ext coarse.$ext; done
cp a.poly same.poly
# together "ARGS A" "ARGS B": both runs started at once, their stderr in err.a and err.b, their
# exits in sa and sb; true when both exit 0.
together() {
  "$deltri" $1 2>err.a &
  pa=$!
  "$deltri" $2 2>err.b &
  pb=$!
  wait $pa; sa=$?
  wait $pb; sb=$?
  [ $sa = 0 ] && [ $sb = 0 ]
}
pairs=${PAIRS:-20} i=0 met=0
while [ $i -lt "$pairs" ]; do
  rm -f a.1.* b.1.* same.1.*
  together "-pq30Q a.poly" "-pq30Q b.poly" || fail "together, other names, pair $i: exit $sa and $sb"
  if [ -s err.a ] || [ -s err.b ]; then fail "together, other names, pair $i: warned: $(cat err.a err.b)"; fi
  for ext in node ele poly; do
    cmp -s a.1.$ext big.$ext && cmp -s b.1.$ext big.$ext || fail "together, other names, pair $i: a.1.$ext or b.1.$ext not as alone"
  done
  together "-pQ same.poly" "-pq30Q same.poly" || fail "together, same names, pair $i: exit $sa and $sb"
  [ -s err.a ] || [ -s err.b ] && met=$((met + 1))
  set_is=$(set_of same coarse big)
  [ $set_is != mixed ] || fail "together, same names, pair $i: a mixed set"
  i=$((i + 1))
done
echo "started together: $pairs pairs on other names, $pairs on the same names ($met of them met each other)"
[ -z "$(ls -a | grep -e '\.tmp\.' -e '^\.deltri-lock')" ] || fail "left behind: $(ls -a | grep -e '\.tmp\.' -e '^\.deltri-lock')"
[ $failed = 0 ] && echo ok
exit $failed
