#!/bin/sh
# A signal between two renames of the outputs onto their final names (issue 47.9) must not leave a
# mixed set (a new .node beside an old .ele): the run ends by the signal with either the old set
# or the new one complete, and no temporary or lock file left. The moment is reached with a
# preloaded hook (rename_hook.c) that sends SIGTERM right after the first rename; --threads=1
# renames one file after the other, so the others are still to do then. Where no output was there
# before, the files are linked at their names from unnamed files (issue 45): a signal right after
# the first link must not leave a partial set either (rounds "fresh").
#   rename_window.sh DELTRI RENAME_HOOK DATA_DIR
set -u
deltri=$1 hook=$2 data=$3
work=$(mktemp -d) || exit 1
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
cp "$data/guitar.poly" .
# An ASan build refuses a preloaded library that comes before its runtime.
LD_PRELOAD=$hook "$deltri" --version >/dev/null 2>&1 || { echo "skipped: the hook cannot be preloaded here"; exit 77; }
failed=0
fail() { echo "FAIL: $*"; failed=1; }
# The two sets: old (-pQ) and new (-pq30Q, more triangles), each made in full first.
for set in old:-pQ new:-pq30Q; do
  name=${set%%:*}
  "$deltri" --threads=1 ${set#*:} guitar.poly || exit 1
  for ext in node ele poly; do mv guitar.1.$ext $name.$ext; done
done
cmp -s old.ele new.ele && { echo "FAIL: the two sets do not differ"; exit 1; }
# which: the set the output files all belong to ("old" or "new"), or "mixed".
which() {
  for name in old new; do
    same=1
    for ext in node ele poly; do cmp -s guitar.1.$ext $name.$ext || same=0; done
    [ $same = 1 ] && { echo $name; return; }
  done
  echo mixed
}
for round in 1 2 3 fresh fresh; do
  for ext in node ele poly; do cp old.$ext guitar.1.$ext; done
  [ $round = fresh ] && rm -f guitar.1.*
  DELTRI_TEST_RENAME_HOOK=term LD_PRELOAD=$hook "$deltri" --threads=1 -pq30Q guitar.poly 2>err
  status=$?
  result=$(which)
  left=$(ls -a | grep -c -e '\.tmp\.' -e '^\.deltri-lock')
  echo "round $round: exit $status, outputs: $result, temporaries and lock files left: $left"
  [ $status = 143 ] || fail "round $round: the run was not ended by SIGTERM (exit $status): $(cat err)"
  [ "$result" = new ] || fail "round $round: after SIGTERM between the renames the outputs are '$result', not the new set"
  [ "$left" = 0 ] || fail "left behind: $(ls -a | grep -e '\.tmp\.' -e '^\.deltri-lock' | tr '\n' ' ')"
done
[ $failed = 0 ] && echo ok
exit $failed
