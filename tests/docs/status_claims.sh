#!/bin/sh
# The docs' claims about what works (issue 19: manual.md and formats.md said -r and .area were
# "not available yet" after both worked), checked against the program:
#   status_claims.sh SOURCE_DIR DELTRI
# 1. no page in docs/ nor the README says a feature is "not available/reachable/implemented yet";
# 2. the manual's status table has nothing in its "accepted, not available yet" column, and
#    formats.md says .ele and .area are read;
# 3. what those lines promise runs: -r with an .area file (deltri -rpqa box.1) and an .area named
#    as the input (deltri -pqa box.1.area) refine box.1 without a notice, into box.2 whose every
#    triangle meets the file's bound (areas computed here from box.2.node/.ele); and the -h text
#    on -s is the manual's.
set -u
src=$1 deltri=$(cd "$(dirname "$2")" && pwd)/$(basename "$2")
work=$(mktemp -d) || exit 1
trap 'rm -rf "$work"' EXIT
failed=0
fail() { echo "FAIL: $*"; failed=1; }

stale=$(grep -n -i -E 'not (yet )?(available|reachable|implemented)( yet)?' "$src"/docs/*.md "$src/README.md" |
        grep -v -F '| works | accepted, not available yet | rejected |')
[ -z "$stale" ] || fail "the docs still say something is not available: $stale"
row=$(grep -A 2 -F '| works | accepted, not available yet | rejected |' "$src/docs/manual.md" | sed -n 3p)
case $row in
  *' -r '*'| — | — |') ;;
  *) fail "manual.md's status table: -r not in 'works', or something accepted but not available: $row" ;;
esac
grep -q -x -F '| `.ele` | yes, with `-r` (the mesh to refine), or named as the input | always (unless `-E`) |' "$src/docs/formats.md" ||
  fail "formats.md's table does not say .ele is read with -r"
grep -q -x -F '| `.area` | yes, with `-r` and a bare `-a`, or named as the input | never (input only) |' "$src/docs/formats.md" ||
  fail "formats.md's table does not say .area is read with -r -a"

# An .area file bounding every triangle of box.1 at 0.002 (box.poly is 3 x 3 with a 1 x 1 hole).
cd "$work" || exit 1
cp "$src/data/box.poly" .
"$deltri" -pq30Q box.poly || fail "deltri -pq30 box.poly failed"
triangles() { awk '!/^[[:space:]]*(#|$)/ { print $1; exit }' "$1"; }
before=$(triangles box.1.ele)
awk -v n="$before" 'BEGIN { print n; for (i = 1; i <= n; i++) print i, 0.002 }' >box.1.area
for command in "-rpqa box.1" "-pqa box.1.area"; do
  rm -f box.2.*
  # shellcheck disable=SC2086  # the switches and the name are two words
  "$deltri" $command >out 2>err
  status=$?
  [ $status = 0 ] || fail "deltri $command: exit $status: $(cat err)"
  [ ! -s err ] || fail "deltri $command printed on stderr: $(cat err)"
  [ -s box.2.node ] && [ -s box.2.ele ] || { fail "deltri $command wrote no box.2.node/.ele"; continue; }
  largest=$(awk '!/^[[:space:]]*(#|$)/ { if (FILENAME != file) { file = FILENAME; header = 1 } else header = 0 }
                 header { next }
                 FILENAME ~ /node$/ && NF >= 3 { x[$1] = $2; y[$1] = $3 }
                 FILENAME ~ /ele$/ && NF >= 4 { a = ((x[$3] - x[$2]) * (y[$4] - y[$2]) - (x[$4] - x[$2]) * (y[$3] - y[$2])) / 2
                                                if (a > m) m = a }
                 END { printf "%.6g", m }' box.2.node box.2.ele)
  after=$(triangles box.2.ele)
  echo "deltri $command: $before -> $after triangles, the largest of area $largest"
  awk "BEGIN { exit !($largest > 0 && $largest <= 0.002 * (1 + 1e-9) && $after > $before) }" ||
    fail "deltri $command: the largest triangle of box.2 has area $largest, the .area file's bound is 0.002"
done

# -h on -s, as the manual's switch list gives it.
want=$(grep -m 1 -E '^  -s  ' "$src/docs/manual.md")
[ -n "$want" ] || fail "no -s line in the manual's switch list"
"$deltri" -h | grep -q -x -F -- "$want" || fail "-h on -s: '$("$deltri" -h | grep -E '^  -s ')', the manual: '$want'"

[ $failed = 0 ] && echo "docs: nothing marked as not available; -r with .area works as formats.md says; -h on -s as in the manual"
exit $failed
