#!/bin/sh
# The batch recipes of docs/manual.md ("Meshing a folder in parallel"):
#   batch_recipe.sh DELTRI DATA_DIR DOCS_DIR
# 1. the xargs line, taken verbatim from the manual, in a copy of data/*.poly;
# 2. docs/examples/batch.mk with make -j2 in another copy, then again: nothing may be remade (told
#    by make -q and by the files' times, not by make's messages, which MAKEFLAGS=-s would silence);
#    each .poly must give a non-empty .1.node/.1.ele/.1.poly, and the two recipes the same bytes;
# 3. a folder with box.poly and a kept Triangle output box.1.poly (+ box.1.node): both recipes and
#    `make clean` must leave box.1.poly and box.1.node as they were, mesh box.1.poly, say why
#    box.poly was left out, and clean must remove exactly what the runs wrote.
set -u
# How the surrounding make was called (-s, -j, -n...) must not change what this test sees.
unset MAKEFLAGS MFLAGS MAKELEVEL MAKEOVERRIDES GNUMAKEFLAGS
deltri=$1 data=$2 docs=$3
work=$(mktemp -d) || exit 1
trap 'rm -rf "$work"' EXIT
failed=0
fail() { echo "FAIL: $*"; failed=1; }
mk="$docs/examples/batch.mk"

line=$(grep -m 1 '^sh .*batch-inputs[.]sh | xargs' "$docs/manual.md")
[ -n "$line" ] || { echo "FAIL: no 'sh .../batch-inputs.sh | xargs' line in the manual"; exit 1; }
echo "recipe: $line"
line=$(printf '%s\n' "$line" | sed "s|/path/to/deltri/docs/|$docs/|")
# The manual's line calls `deltri`; put this build first on PATH.
mkdir "$work/bin" && ln -s "$deltri" "$work/bin/deltri"
xargs_recipe() { (cd "$1" && PATH="$work/bin:$PATH" sh -c "$line" 2>"$work/xargs.err"); }
make_recipe() { (cd "$1" && shift && make -f "$mk" DELTRI="$deltri" "$@"); }

# ---- 1, 2: every data/*.poly ----
mkdir "$work/x" "$work/m"
cp "$data"/*.poly "$work/x" && cp "$data"/*.poly "$work/m"
xargs_recipe "$work/x" || fail "the xargs recipe failed: $(cat "$work/xargs.err")"
make_recipe "$work/m" -s -j2 || fail "make -j2 -f batch.mk failed"
stamp() { (cd "$1" && ls -l --time-style=+%s.%N | LC_ALL=C sort); }
before=$(stamp "$work/m")
make_recipe "$work/m" -q || fail "make -q: batch.mk is not up to date after a run"
make_recipe "$work/m" -s -j2 || fail "a second make -j2 -f batch.mk failed"
[ "$before" = "$(stamp "$work/m")" ] || fail "a second make remade meshes"
count=0
for poly in "$data"/*.poly; do
  b=$(basename "$poly" .poly)
  for ext in node ele poly; do
    [ -s "$work/x/$b.1.$ext" ] || fail "xargs: $b.1.$ext missing or empty"
    cmp -s "$work/x/$b.1.$ext" "$work/m/$b.1.$ext" || fail "$b.1.$ext differs between the two recipes"
  done
  grep -q "\"files\":\[.*\"$b.1.poly\"" "$work/m/$b.poly.json" || fail "$b.poly.json does not list $b.1.poly"
  count=$((count + 1))
done
[ $count -ge 10 ] || fail "only $count .poly files in $data"
[ $failed = 0 ] && echo "batch: $count meshes by xargs -P and by make -j, identical; a second make remade nothing"

# ---- 3: a kept Triangle output beside its input ----
kept="$work/kept"
mkdir "$kept" && cp "$data/box.poly" "$kept/"
(cd "$kept" && "$deltri" -pQ box.poly && rm box.1.ele) || fail "could not make box.1.poly"
cp "$kept/box.1.poly" "$work/box.1.poly.orig" && cp "$kept/box.1.node" "$work/box.1.node.orig"
inputs_intact() {
  cmp -s "$kept/box.1.poly" "$work/box.1.poly.orig" || fail "$1: box.1.poly was overwritten or deleted"
  cmp -s "$kept/box.1.node" "$work/box.1.node.orig" || fail "$1: box.1.node was overwritten or deleted"
  [ -f "$kept/box.poly" ] || fail "$1: box.poly was deleted"
}
expected_left_out="batch-inputs.sh: box.poly not meshed: deltri would write box.1.node over an input here (rename one of them)"
xargs_recipe "$kept" || fail "the xargs recipe failed on box.poly + box.1.poly: $(cat "$work/xargs.err")"
[ "$(cat "$work/xargs.err")" = "$expected_left_out" ] || fail "xargs: stderr was '$(cat "$work/xargs.err")'"
inputs_intact "xargs recipe"
[ -s "$kept/box.2.ele" ] || fail "xargs: box.1.poly was not meshed (no box.2.ele)"
xargs_files=$(cd "$kept" && ls | LC_ALL=C sort | tr '\n' ' ')
make_recipe "$kept" -s clean || fail "make clean failed"
inputs_intact "make clean after the xargs recipe"
left=$(cd "$kept" && ls | LC_ALL=C sort | tr '\n' ' ')
[ "$left" = "box.1.node box.1.poly box.poly " ] || fail "after clean: $left"
err=$(make_recipe "$kept" -s -j2 2>&1) || fail "make on box.poly + box.1.poly failed: $err"
[ "$err" = "$expected_left_out" ] || fail "make: output was '$err'"
inputs_intact "make"
now=$(cd "$kept" && ls | LC_ALL=C sort | tr '\n' ' ')
[ "$now" = "$xargs_files" ] || fail "make wrote '$now', xargs '$xargs_files'"
make_recipe "$kept" -s clean || fail "make clean failed"
inputs_intact "make clean"
left=$(cd "$kept" && ls | LC_ALL=C sort | tr '\n' ' ')
[ "$left" = "box.1.node box.1.poly box.poly " ] || fail "after clean: $left"
[ $failed = 0 ] && echo "batch: box.poly beside a kept box.1.poly/.node: left out with a reason, box.1.poly meshed to box.2.*, the kept files intact after both recipes and clean ($xargs_files)"
exit $failed
