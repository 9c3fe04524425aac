#!/bin/sh
# make check-fresh: the README's two commands, `make demo` then `make test`, as a newcomer runs them:
# in a fresh clone of this checkout's HEAD (committed work only), from a clean environment
# (env -i with PATH=/usr/bin:/bin and a new HOME: no ccache, no CMAKE_* or MAKEFLAGS from here).
#   check_fresh.sh SOURCE_DIR
# 1. MAKEFLAGS unset: the full build, the demo and every test;
# 2. MAKEFLAGS=-s in the same clone: the same two commands again. Nothing is rebuilt, so this run
#    costs one more test run, and it shows that how make is called changes no test's outcome.
# Fails when any of the four commands fails. Not part of `make test` (it runs `make test` itself).
set -u
src=$1
work=$(mktemp -d "${TMPDIR:-/tmp}/deltri-fresh.XXXXXX") || exit 1
trap 'rm -rf "$work"' EXIT
head=$(git -C "$src" rev-parse HEAD) || exit 1
git clone -q --no-local "$src" "$work/deltri" && git -C "$work/deltri" checkout -q "$head" || {
  echo "check-fresh: could not clone $src"
  exit 1
}
mkdir "$work/home"
echo "check-fresh: fresh clone of $head in $work/deltri"
failed=0
step() {  # LABEL MAKEFLAGS_OR_EMPTY TARGET
  label=$1 flags=$2 target=$3
  started=$(date +%s)
  if [ -n "$flags" ]; then
    (cd "$work/deltri" && env -i PATH=/usr/bin:/bin HOME="$work/home" MAKEFLAGS="$flags" make "$target") >"$work/log" 2>&1
  else
    (cd "$work/deltri" && env -i PATH=/usr/bin:/bin HOME="$work/home" make "$target") >"$work/log" 2>&1
  fi
  status=$?
  took=$(($(date +%s) - started))
  if [ $status = 0 ]; then
    echo "check-fresh: $label: make $target: ok in $took s; $(grep -E '^demo: |tests passed|tests failed' "$work/log" | tail -n 1)"
  else
    echo "check-fresh: $label: make $target FAILED (exit $status) after $took s; its output:"
    cat "$work/log"
    failed=1
  fi
}
step "MAKEFLAGS unset" "" demo
step "MAKEFLAGS unset" "" test
step "MAKEFLAGS=-s" "-s" demo
step "MAKEFLAGS=-s" "-s" test
[ $failed = 0 ] && echo "check-fresh: the README's two commands pass in a fresh clone, with MAKEFLAGS unset and with -s"
exit $failed
