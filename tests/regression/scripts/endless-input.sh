#!/bin/sh
# Issue 17 item 4: endless non-regular inputs must fail at once, not fill memory first:
# /dev/zero and /dev/urandom named as a .node, and `yes garbage` on standard input.
# Memory is capped (ulimit -v) so that reading on until memory runs out fails differently and
# the loop cannot take the machine down; the timeout is only a guard.
#   endless-input.sh DELTRI
set -u
deltri=$1
work=$(mktemp -d) || exit 1
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
fail=0
# AddressSanitizer reserves terabytes of shadow address space and cannot start under ulimit -v;
# a sanitized build gets its cap from ASan's own RSS limit instead.
cap=1000000
if grep -q __asan_init "$deltri" 2>/dev/null; then
  cap=unlimited
  export ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}hard_rss_limit_mb=1500"
fi
check() {  # label status
  echo "$1: exit $2: $(head -n 1 stderr)"
  [ "$2" -eq 1 ] || { echo "FAIL: $1 should fail with exit 1"; fail=1; return; }
  # Line 1 almost always; /dev/urandom may start with a digit by chance and fail a line later.
  head -n 1 stderr | grep -q "^[a-z. ]*:[0-9][0-9]*: " || { echo "FAIL: $1: not a file:line error"; fail=1; }
}
for dev in /dev/zero /dev/urandom; do
  ln -sf "$dev" u.node
  (ulimit -v $cap; timeout 60 "$deltri" u.node) >/dev/null 2>stderr
  check "$dev" $?
done
(ulimit -v $cap; yes garbage | timeout 60 "$deltri" -) >/dev/null 2>stderr
check "yes garbage" $?
[ $fail -eq 0 ] && echo ok
exit $fail
