#!/bin/sh
# Issue 17 item 6: SIGINT, SIGTERM or SIGHUP while deltri writes its outputs must remove the
# NAME.tmp.* temporaries (and end the run by that signal); after SIGKILL, which no handler sees,
# the next run on the same output names removes them, since their process is gone, and says so.
#   interrupted-write.sh DELTRI
set -u
deltri=$1
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d) || exit 1
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
cp "$here/../../../data/guitar.poly" .
fail=0
# Starts a run big enough that its write takes a while, waits until its temporaries exist, then
# sends the signal. env --default-signal: a background job of sh starts with SIGINT ignored.
# On a busy machine the run may finish its write before this shell sees the temporaries or sends
# the signal (exit 0): that attempt shows nothing, and the run is started again (up to 10 times).
interrupt() {  # signal
  attempt=0 status=0
  while [ $status = 0 ] && [ $attempt -lt 10 ]; do
    attempt=$((attempt + 1))
    rm -f guitar.1.*
    env --default-signal=INT "$deltri" -Qpqa0.0001 guitar.poly >/dev/null 2>stderr &
    pid=$!
    i=0
    while [ $i -lt 6000 ] && ! ls guitar.1.*.tmp.* >/dev/null 2>&1 && kill -0 $pid 2>/dev/null; do
      sleep 0.01
      i=$((i + 1))
    done
    kill -"$1" $pid 2>/dev/null
    wait $pid
    status=$?
  done
}
for sig in INT TERM HUP; do
  interrupt $sig
  left=$(ls guitar.1.* 2>/dev/null | tr '\n' ' ')
  echo "SIG$sig: exit $status, left: ${left:-nothing}"
  [ $status -gt 128 ] || { echo "FAIL: the run was not ended by the signal"; fail=1; }
  [ -z "$left" ] || { echo "FAIL: files left after SIG$sig"; fail=1; }
done
interrupt KILL
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
