#!/bin/sh
# -r end to end (called by CTest, see cases.cmake):  refine_chain.sh DELTRI VERIFY INPUT.poly
# 1. -pq30 writes X.1.*; -rp on X.1 must reproduce X.1's .node, .ele and .poly byte for byte as X.2.*.
# 2. -rpq33 on X.1 must give a valid mesh of the original input (deltri_mesh_verify) whose
#    smallest angle, computed here from the files, is at least 33 degrees (the input has none smaller).
# 3. -rq30a with an area bound: every triangle's area, computed here, is at most the bound.
# 4. A .ele with a clockwise triangle is refused: exit 1, "X.1.ele: ..." and no output files.
set -u
deltri=$1 verify=$2 input=$3
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d) || exit 1
trap 'rm -rf "$work"' EXIT
failed=0
fail() { echo "FAIL: $*"; failed=1; }
name=$(basename "$input" .poly)
cp "$input" "$work/$name.poly"
cd "$work" || exit 1

"$deltri" -pq30Q "$name.poly" || fail "-pq30 failed"
"$deltri" -rpQ "$name.1" || fail "-rp failed"
for ext in node ele poly; do cmp -s "$name.1.$ext" "$name.2.$ext" || fail "-rp changed the .$ext"; done

. "$here/measure.sh"

rm -f "$name".2.*
"$deltri" -rpq33Q "$name.1" || fail "-rpq33 failed"
"$verify" --input "$name.poly" --mesh "$name.2" --refined || fail "-rpq33: deltri_mesh_verify found faults"
set -- $(measure "$name.2")
awk -v a="$1" 'BEGIN { exit !(a >= 33) }' || fail "-rpq33: smallest angle $1 < 33"
echo "-rpq33: smallest angle $1"

rm -f "$name".2.*
"$deltri" -rq30a0.5Q "$name.1" || fail "-rq30a0.5 failed"
set -- $(measure "$name.2")
awk -v a="$2" 'BEGIN { exit !(a <= 0.5) }' || fail "-rq30a0.5: largest area $2 > 0.5"
awk -v a="$1" 'BEGIN { exit !(a >= 30) }' || fail "-rq30a0.5: smallest angle $1 < 30"
echo "-rq30a0.5: smallest angle $1, largest area $2"

rm -f "$name".2.*
awk 'NR == 2 && !/^#/ { t = $3; $3 = $4; $4 = t } { print }' "$name.1.ele" >bad.ele
head -n 1 "$name.1.ele" | grep -q . && mv bad.ele "$name.1.ele"
"$deltri" -rpq30Q "$name.1" 2>err
status=$?
[ $status = 1 ] || fail "a clockwise .ele: exit $status, expected 1"
grep -q "^$name.1.ele: .*counter-clockwise" err || fail "a clockwise .ele: message was '$(cat err)'"
ls "$name".2.* >/dev/null 2>&1 && fail "a refused -r run left output files"
exit $failed
