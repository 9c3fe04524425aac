#!/bin/sh
# Issue 17 item 6: SIGINT, SIGTERM or SIGHUP while deltri writes its outputs must remove the
# NAME.tmp.* temporaries (and end the run by that signal); after SIGKILL, which no handler sees,
# the next run on the same output names removes them, since their process is gone, and says so.
# Where no output was there before, the files are written unnamed (O_TMPFILE, issue 45) where the
# file system allows: any signal then, SIGKILL too, leaves nothing at all. Where the old outputs
# are there, they stay as they were.
#   interrupted-write.sh DELTRI
set -u
deltri=$1
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d) || exit 1
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
cp "$here/../../../data/guitar.poly" .
fail=0
# writing PID [old]: whether run PID has its outputs open: named temporaries, or (without "old",
# where no outputs were there) unnamed files, shown in /proc/PID/fd as DIR/#INODE (deleted).
writing() {
  ls guitar.1.*.tmp.* >/dev/null 2>&1 ||
    { [ $# = 1 ] && ls -l /proc/$1/fd 2>/dev/null | grep -q '/#[0-9]* (deleted)'; }
}
# Starts a run big enough that its write takes a while, waits until it writes, then sends the
# signal. With "old", the old outputs (old.*) are put in place first. env --default-signal: a
# background job of sh starts with SIGINT ignored. On a busy machine the run may finish its
# write before this shell sees it or sends the signal (exit 0): that attempt shows nothing, and
# the run is started again (up to 10 times).
"$deltri" -pQ guitar.poly && for ext in node ele poly; do mv guitar.1.$ext old.$ext; done
interrupt() {  # signal [old]
  attempt=0 status=0
  while [ $status = 0 ] && [ $attempt -lt 10 ]; do
    attempt=$((attempt + 1))
    rm -f guitar.1.*
    [ $# -gt 1 ] && for ext in node ele poly; do cp old.$ext guitar.1.$ext; done
    env --default-signal=INT "$deltri" -Qpqa0.0001 guitar.poly >/dev/null 2>stderr &
    pid=$!
    i=0
    while [ $i -lt 6000 ] && ! writing $pid ${2:-} && kill -0 $pid 2>/dev/null; do
      sleep 0.01
      i=$((i + 1))
    done
    kill -"$1" $pid 2>/dev/null
    wait $pid
    status=$?
  done
}
# old_kept: the old outputs are there as they were, and nothing else of the run.
old_kept() {
  for ext in node ele poly; do cmp -s guitar.1.$ext old.$ext || return 1; done
  [ "$(ls guitar.1.* | wc -l)" -eq 3 ]
}
for case in INT TERM HUP INT:old HUP:old; do
  sig=${case%:old}
  if [ $sig = $case ]; then interrupt $sig; else interrupt $sig old; fi
  left=$(ls guitar.1.* 2>/dev/null | tr '\n' ' ')
  echo "SIG$case: exit $status, left: ${left:-nothing}"
  [ $status -gt 128 ] || { echo "FAIL: the run was not ended by the signal"; fail=1; }
  if [ $sig = $case ]; then
    [ -z "$left" ] || { echo "FAIL: files left after SIG$sig"; fail=1; }
  else
    old_kept || { echo "FAIL: the old outputs were not kept as they were after SIG$sig"; fail=1; }
  fi
done
interrupt KILL
finals=$(ls guitar.1.node guitar.1.ele guitar.1.poly 2>/dev/null | tr '\n' ' ')
echo "SIGKILL, no outputs before: exit $status, output files left: ${finals:-none}"
[ -z "$finals" ] || { echo "FAIL: a run killed while writing left output files"; fail=1; }
interrupt KILL old
stale=$(ls guitar.1.*.tmp.* 2>/dev/null | wc -l)
echo "SIGKILL: exit $status, $stale temporaries left"
[ "$stale" -gt 0 ] || { echo "FAIL: expected the killed run's temporaries"; fail=1; }
"$deltri" -Qpq guitar.poly 2>stderr
status=$?
sed 's/^/  next run: /' stderr
left=$(ls guitar.1.*.tmp.* 2>/dev/null | wc -l)
[ $status -eq 0 ] && [ "$left" -eq 0 ] || { echo "FAIL: the next run left $left temporaries (exit $status)"; fail=1; }
grep -q "removed $stale temporary file" stderr || { echo "FAIL: the next run did not report the removal"; fail=1; }
[ $fail -eq 0 ] && echo ok
exit $fail
