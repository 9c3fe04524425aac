#!/bin/sh
# One output directory reached through two paths (issue 47.10): the run must not lock it twice and
# wait for itself. The outputs of guitar.poly go to its folder as guitar.1.*, and --msh names the
# same folder another way: through a symbolic link, and through a bind mount (as in containers:
# in a private mount namespace, `unshare -m`, so nothing outlives the test). An output named
# through the other path as one of the run's own files is one file and is refused.
# `timeout` only ends a run that hangs; a correct run takes well under a second.
#   lock_aliases.sh DELTRI DATA_DIR      (HANG_SECONDS in the environment: the timeout, 600 s)
set -u
deltri=$1 data=$2
work=$(mktemp -d) || exit 1
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
mkdir real bound
cp "$data/guitar.poly" real/
ln -s real linked
failed=0
fail() { echo "FAIL: $*"; failed=1; }
# run_in ALIAS [PREFIX...]: meshes real/guitar.poly with --msh under ALIAS/, then an output that
# is the .ele under another name.
run_in() {
  alias=$1
  shift
  rm -f real/guitar.1.*
  "$@" timeout "${HANG_SECONDS:-600}" "$deltri" -pQ --msh="$alias/guitar.1.msh" real/guitar.poly 2>err
  status=$?
  [ $status = 0 ] || fail "--msh through $alias: exit $status (124: it hung) $(cat err)"
  for f in guitar.1.node guitar.1.ele guitar.1.poly guitar.1.msh; do
    [ -s real/$f ] || fail "--msh through $alias: real/$f missing"
  done
  rm -f real/guitar.1.*
  "$@" timeout "${HANG_SECONDS:-600}" "$deltri" -pQ --msh="$alias/guitar.1.ele" real/guitar.poly 2>err
  status=$?
  [ $status = 4 ] || fail "--msh=$alias/guitar.1.ele: exit $status, expected 4"
  grep -q "guitar.1.ele: the same file as real/guitar.1.ele, another output of this run (no files written)" err ||
    fail "--msh=$alias/guitar.1.ele: message '$(cat err)'"
  [ -z "$(ls real | grep -v -x guitar.poly)" ] || fail "--msh=$alias/guitar.1.ele: files written: $(ls real)"
  echo "through $alias: ok so far ($failed)"
}
run_in linked
# The bind mount, where mounting is allowed (root in a namespace that may mount).
if unshare -m sh -c "mount --bind real bound" 2>/dev/null; then
  run_in bound unshare -m sh -c 'mount --bind real bound && exec "$@"' sh
else
  echo "skipped: a bind mount is not allowed here"
  [ $failed = 0 ] && exit 77
fi
[ $failed = 0 ] && echo ok
exit $failed
