#!/bin/sh
# Issue 17 item 3: an input file that another process truncates while deltri reads it must give
# the ordinary error (or, if the truncation comes after the read, a normal run), never a crash.
# Inputs of 4 MB or more used to be mapped, and a shrink killed deltri with SIGBUS (exit 135).
#   shrinking-input.sh DELTRI
set -u
deltri=$1
work=$(mktemp -d) || exit 1
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
# About 24 MB of vertices, then a bad line so that a complete read fails quickly after parsing.
/usr/bin/python3 -c '
import random
random.seed(17)
n = 600000
with open("big.node", "w") as f:
    f.write("%d 2 0 0\n" % (n + 1))
    for i in range(1, n + 1):
        f.write("%d %.17g %.17g\n" % (i, random.random(), random.random()))
    f.write("%d not-a-number 0\n" % (n + 1))
'
cp big.node pristine.node
crashes=0
for delay in 0 0.01 0.02 0.05 0.1 0.15 0.2 0.3; do
  cp pristine.node big.node
  "$deltri" -Q big.node >/dev/null 2>stderr &
  pid=$!
  sleep $delay
  : > big.node  # shrink to nothing while deltri may be reading or parsing
  wait $pid
  status=$?
  echo "truncated after ${delay}s: exit $status: $(head -n 1 stderr)"
  case $status in
    1) grep -q '^big.node' stderr || { echo "FAIL: error not about big.node"; crashes=$((crashes + 1)); } ;;
    *) echo "FAIL: exit status $status"; crashes=$((crashes + 1)) ;;
  esac
done
[ $crashes -eq 0 ] || exit 1
echo "ok"
