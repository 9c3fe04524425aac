#!/bin/sh
# --each (issue 45: many files in one process): every input named is meshed as if alone.
#   - two good inputs and a truncated one: both good meshes written, each the same files as the
#     input meshed alone and passing deltri_mesh_verify at -q30; nothing for the bad one; its
#     error line, then the count of failures; the exit status the bad input's (1);
#   - without --each the last input named is the input, as in Triangle: one mesh;
#   - --json alone writes one report per input; --json=FILE with two inputs is refused (exit 2)
#     before anything is written.
#   each.sh DELTRI VERIFY DATA_DIR
set -u
deltri=$1 verify=$2 data=$3
work=$(mktemp -d) || exit 1
trap 'rm -rf "$work"' EXIT
failed=0
fail() { echo "FAIL: $*"; failed=1; }
mkdir "$work/each" "$work/alone"
for d in each alone; do cp "$data/guitar.poly" "$data/box.poly" "$work/$d/"; done
printf '3 2 0 0\n1 0 0\n2 1 0\n' >"$work/each/bad.poly"

cd "$work/alone" || exit 1
for f in guitar box; do "$deltri" -pq30Q $f.poly || fail "deltri -pq30Q $f.poly alone: exit $?"; done

cd "$work/each" || exit 1
"$deltri" -pq30Q --each guitar.poly bad.poly box.poly 2>err
status=$?
[ $status = 1 ] || fail "--each with a bad input: exit $status, expected 1"
grep -q -x 'bad.poly:3: .*' err || fail "--each: no error line for bad.poly: $(cat err)"
want="deltri: --each: 1 of 3 inputs did not end with status 0: bad.poly (status 1)"
[ "$(tail -n 1 err)" = "$want" ] || fail "--each: last line '$(tail -n 1 err)', expected '$want'"
[ "$(wc -l <err)" = 2 ] || fail "--each: expected two lines on stderr: $(cat err)"
ls bad.1.* >/dev/null 2>&1 && fail "--each: files written for bad.poly: $(ls bad.1.*)"
for f in guitar box; do
  for ext in node ele poly; do
    cmp -s "$f.1.$ext" "../alone/$f.1.$ext" || fail "--each: $f.1.$ext differs from $f.poly meshed alone"
  done
  "$verify" --input $f.poly --mesh $f.1 --refined --min-angle 30 >/dev/null || fail "--each: $f.1 fails the verifier"
done
rm -f ./*.1.*

"$deltri" -pq30Q guitar.poly box.poly 2>err || fail "two inputs without --each: exit $?: $(cat err)"
[ -f box.1.ele ] && [ ! -e guitar.1.ele ] || fail "two inputs without --each: expected box.1.* only: $(ls)"
rm -f ./*.1.*

"$deltri" -pq30Q --each --json guitar.poly box.poly 2>err || fail "--each --json: exit $?: $(cat err)"
for f in guitar box; do
  /usr/bin/python3 -c "import json, sys; r = json.load(open(sys.argv[1])); assert r['input'] == sys.argv[2], r['input']" \
    $f.1.json $f.poly || fail "--each --json: $f.1.json is not $f.poly's report"
done
rm -f ./*.1.*

"$deltri" -pq30Q --each --json=r.json guitar.poly box.poly 2>err
status=$?
[ $status = 2 ] || fail "--each --json=r.json: exit $status, expected 2"
want="deltri: --each: --json=r.json names one file for 2 inputs; give --json alone to write one beside each input's mesh"
[ "$(cat err)" = "$want" ] || fail "--each --json=r.json: said '$(cat err)'"
[ -z "$(ls ./*.1.* r.json 2>/dev/null)" ] || fail "--each --json=r.json: files written: $(ls)"

[ $failed = 0 ] && echo "each: ok"
exit $failed
