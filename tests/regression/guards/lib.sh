# Helpers for the scripts in this directory (sourced): each script takes DELTRI VERIFY, runs
# deltri in a scratch folder and exits 0 on success. CTest's timeout (cases.cmake) is the guard
# against a hang; nothing here measures time.
set -u
deltri=$1 verify=$2
work=$(mktemp -d) || exit 1
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1

fail() { echo "FAIL: $*"; exit 1; }

# run EXPECTED_STATUS SWITCHES... FILE: runs deltri, keeps its stderr in stderr.last, checks the status.
run() {
  want=$1
  shift
  "$deltri" "$@" >/dev/null 2>stderr.last
  got=$?
  echo "deltri $*: exit $got"
  sed 's/^/  stderr: /' stderr.last
  [ "$got" -eq "$want" ] || fail "deltri $* exited $got, expected $want"
}

# verified INPUT OUTBASE: the output passes deltri_mesh_verify as a refined mesh of INPUT.
verified() {
  "$verify" --input "$1" --mesh "$2" --refined || fail "$2 does not pass deltri_mesh_verify"
}

# counted_misses: the last run warned of its triangles that miss the bounds, with their number.
counted_misses() {
  grep -Eq "warning: .*: [0-9]+ triangles? miss(es)? the requested bounds" stderr.last ||
    fail "no warning with a count of the triangles that miss the bounds"
}

# ends_counted INPUT OUTBASE SWITCHES... FILE: deltri SWITCHES... FILE exits 0 and counts its misses,
# and OUTBASE is a verified refined mesh of INPUT (for -r, INPUT is the earlier run's .poly).
ends_counted() {
  input=$1 out=$2
  shift 2
  run 0 "$@" && counted_misses && verified "$input" "$out"
}

# ends_verified INPUT OUTBASE SWITCHES... FILE: as ends_counted, without requiring misses.
ends_verified() {
  input=$1 out=$2
  shift 2
  run 0 "$@" && verified "$input" "$out"
}
