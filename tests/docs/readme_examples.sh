#!/bin/sh
# The README's first examples, pasted as a newcomer would from the repository root:
#   readme_examples.sh SOURCE_DIR DELTRI
# Run in a scratch folder laid out like the root (data/ -> the samples, build/deltri -> this build);
# every line must succeed and write what its comment says.
set -u
src=$1 deltri=$2
work=$(mktemp -d) || exit 1
trap 'rm -rf "$work"' EXIT
mkdir "$work/build" && ln -s "$deltri" "$work/build/deltri" && ln -s "$src/data" "$work/data"
sed -n '/^    cp data\//,/^    build\/deltri --version/p' "$src/README.md" | sed 's/^    //' >"$work/lines"
[ "$(wc -l <"$work/lines")" -ge 3 ] || { echo "FAIL: no example block in README.md"; exit 1; }
failed=0
while IFS= read -r line; do
  echo "\$ $line"
  (cd "$work" && sh -c "$line") >"$work/out" 2>&1
  status=$?
  [ $status = 0 ] || { failed=1; echo "FAIL: exit status $status"; }
  sed 's/^/  /' "$work/out"
done <"$work/lines"
for f in box.1.node box.1.ele box.1.poly guitar.1.msh guitar.1.vtu guitar.1.svg guitar.msh; do
  [ -s "$work/build/$f" ] || { echo "FAIL: build/$f was not written"; failed=1; }
done
cmp -s "$work/build/guitar.msh" "$work/build/guitar.1.msh" || { echo "FAIL: the piped .msh differs from the file run's"; failed=1; }
[ $failed = 0 ] && echo "README examples: all ran from a root-like folder and wrote their files"
exit $failed
