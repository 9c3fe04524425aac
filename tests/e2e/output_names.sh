#!/bin/sh
# Output names the command line must get right (issue 47.12), each a run that used to succeed with
# a wrong or missing result, or fail where Triangle succeeds:
#   - two outputs of one run naming one file: refused before anything is written (exit 4);
#   - -I with switches that add vertices, when -I withholds the .node: refused (exit 2), as the
#     .ele would name vertices that are in no file; -I alone, and -qIN, still run;
#   - --json with an input name that is not UTF-8: valid JSON (python3's json module, strict
#     UTF-8), the name's bytes kept as \u00XX;
#   - a base name of 240 characters: its outputs (247 characters) are written, although a
#     temporary named after the whole output name would be longer than a file name may be.
#   output_names.sh DELTRI DATA_DIR
set -u
deltri=$1 data=$2
work=$(mktemp -d) || exit 1
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
cp "$data/guitar.poly" "$data/ukraine.node" .
failed=0
fail() { echo "FAIL: $*"; failed=1; }
# The files here besides the inputs.
outputs() { ls -a | grep -v -x -e . -e .. -e guitar.poly -e ukraine.node -e err -e 'g.*x\.poly' -e 'a*\.poly' | tr '\n' ' '; }

# expect STATUS MESSAGE -- ARGS: exit status, stderr's first line, and no file written.
expect_refused() {
  want_status=$1 want=$2
  shift 3
  "$deltri" "$@" 2>err
  status=$?
  [ $status = "$want_status" ] || fail "deltri $*: exit $status, expected $want_status"
  [ "$(head -n 1 err)" = "$want" ] || fail "deltri $*: said '$(cat err)', expected '$want'"
  [ -z "$(outputs)" ] || fail "deltri $*: files written: $(outputs)"
  rm -f -- *.1.* ukraine.ele
}

expect_refused 4 "guitar.1.ele: named by two outputs of this run (no files written)" -- -pQ --msh=guitar.1.node --json=guitar.1.ele guitar.poly
expect_refused 4 "guitar.1.node: named by two outputs of this run (no files written)" -- -pQ --msh=guitar.1.node guitar.poly
expect_refused 4 "guitar.1.vtu: the same file as ./guitar.1.vtu, another output of this run (no files written)" -- -pQ --vtu --msh=./guitar.1.vtu guitar.poly

I_refusal="deltri: -I: -q adds vertices, which only a .node could hold, and -I does not write ukraine.node (it would replace the input's vertices); leave out -I (the outputs are then ukraine.1.*) or add -N if the .node is not wanted"
expect_refused 2 "$I_refusal" -- -qIQ ukraine.node
expect_refused 2 "$(echo "$I_refusal" | sed 's/-q adds/-a adds/')" -- -a50IQ ukraine.node
"$deltri" -IQ ukraine.node 2>err || fail "-I alone: exit $? $(cat err)"
[ "$(outputs)" = "ukraine.ele " ] || fail "-I alone: wrote '$(outputs)', expected ukraine.ele"
rm -f ukraine.ele
"$deltri" -qINQ ukraine.node 2>err || fail "-qIN: exit $? $(cat err)"
[ "$(outputs)" = "ukraine.ele " ] || fail "-qIN: wrote '$(outputs)', expected ukraine.ele"
rm -f ukraine.ele
# With the vertices in the .poly the .node is written under -I, new vertices included.
"$deltri" -pq30IQ guitar.poly 2>err || fail "-pq30I on a .poly: exit $? $(cat err)"
[ -s guitar.node ] && [ -s guitar.ele ] || fail "-pq30I on a .poly: wrote '$(outputs)'"
rm -f guitar.node guitar.ele

name=$(printf 'g\351\377x')
cp guitar.poly "$name.poly"
"$deltri" -pQ --json "$name.poly" 2>err || fail "--json on a Latin-1 name: exit $? $(cat err)"
/usr/bin/python3 - "$name.1.json" <<'PY' || fail "--json on a Latin-1 name: not valid JSON"
import json, os, sys
path = os.fsencode(sys.argv[1])
report = json.loads(open(path, "rb").read().decode("utf-8"))   # strict: a stray byte raises
text = json.dumps(report, ensure_ascii=False)
assert "g\u00e9\u00ffx.poly" in text, "the name's bytes are not kept as U+00E9 U+00FF"
PY
rm -f -- *.1.*

long=$(printf 'a%.0s' $(seq 240))
cp guitar.poly "$long.poly"
"$deltri" -pq30Q "$long.poly" 2>err || fail "a 240-character base name: exit $? $(head -c 300 err)"
for ext in node ele poly; do [ -s "$long.1.$ext" ] || fail "a 240-character base name: $ext not written"; done
[ -z "$(ls -a | grep '\.tmp\.')" ] || fail "a 240-character base name: temporaries left"
[ $failed = 0 ] && echo ok
exit $failed
