#!/bin/sh
# The batch recipes of docs/manual.md ("Meshing a folder in parallel") run over every data/*.poly:
#   batch_recipe.sh DELTRI DATA_DIR DOCS_DIR
# 1. the xargs line, taken verbatim from the manual, in a copy of the folder;
# 2. docs/examples/batch.mk with make -j2 in another copy, then again (nothing to do: no rerun).
# Each .poly must give a non-empty .1.node/.1.ele/.1.poly, and the two recipes the same bytes.
set -u
deltri=$1 data=$2 docs=$3
work=$(mktemp -d) || exit 1
trap 'rm -rf "$work"' EXIT
failed=0
fail() { echo "FAIL: $*"; failed=1; }

line=$(grep -m 1 '^ls \*\.poly | .*xargs' "$docs/manual.md")
[ -n "$line" ] || { echo "FAIL: no 'ls *.poly | xargs' line in the manual"; exit 1; }
echo "recipe: $line"
mkdir "$work/x" "$work/m"
cp "$data"/*.poly "$work/x" && cp "$data"/*.poly "$work/m"
# The manual's line calls `deltri`; put this build first on PATH.
mkdir "$work/bin" && ln -s "$deltri" "$work/bin/deltri"
(cd "$work/x" && PATH="$work/bin:$PATH" sh -c "$line") || fail "the xargs recipe failed"
(cd "$work/m" && make -s -f "$docs/examples/batch.mk" -j2 DELTRI="$deltri") || fail "make -j2 -f batch.mk failed"
again=$(cd "$work/m" && make -f "$docs/examples/batch.mk" -j2 DELTRI="$deltri" 2>&1)
case $again in *"Nothing to be done"*) ;; *) fail "a second make remade meshes: $again" ;; esac
count=0
for poly in "$data"/*.poly; do
  b=$(basename "$poly" .poly)
  for ext in node ele poly; do
    [ -s "$work/x/$b.1.$ext" ] || fail "xargs: $b.1.$ext missing or empty"
    cmp -s "$work/x/$b.1.$ext" "$work/m/$b.1.$ext" || fail "$b.1.$ext differs between the two recipes"
  done
  count=$((count + 1))
done
[ $count -ge 10 ] || fail "only $count .poly files in $data"
[ $failed = 0 ] && echo "batch: $count meshes by xargs -P and by make -j, identical"
exit $failed
