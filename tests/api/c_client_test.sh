#!/bin/sh
# The C library as a user meets it: installed (cmake --install into a scratch prefix), the client
# tests/api/c_client.c compiled with gcc as C99 against the installed <deltri/triangle.h> only,
# linked with -ldeltri through pkg-config, then every case below compared with the command line's
# files for the same input and switches (tests/api/compare_c_client.py).
#   c_client_test.sh SOURCE_DIR BUILD_DIR [SANITIZER_FLAGS]
set -u
src=$1 build=$2 sanitize=${3:-}
command -v pkg-config >/dev/null && command -v gcc >/dev/null ||
  { echo "SKIP: missing pkg-config or gcc; install with: sudo apt-get install -y pkg-config gcc"; exit 77; }
work=$(mktemp -d) || exit 1
trap 'rm -rf "$work"' EXIT
cmake --install "$build" --prefix "$work/prefix" >"$work/log" 2>&1 || { cat "$work/log"; echo "FAIL: cmake --install"; exit 1; }
export PKG_CONFIG_PATH="$work/prefix/lib/pkgconfig"
# Compiled as a user would, plus -Werror; a sanitizer build of the library needs its runtime in the client too.
gcc -std=c99 -pedantic -Wall -Wextra -Werror $sanitize $(pkg-config --cflags deltri) "$src/tests/api/c_client.c" \
    -o "$work/c_client" $(pkg-config --libs deltri) || { echo "FAIL: the C client does not compile against the installed header"; exit 1; }
export LD_LIBRARY_PATH="$work/prefix/lib"
ldd "$work/c_client" | grep -q "$work/prefix/lib/libdeltri.so.0" || { echo "FAIL: the client is not linked with the installed libdeltri.so.0"; exit 1; }
P=$src/tests/api/inputs/plate_attr.poly
D=$src/data
E=$src/tests/e2e/inputs
failed=0
run() { /usr/bin/python3 "$src/tests/api/compare_c_client.py" "$build/deltri" "$work/c_client" "$work/case" "$@" || failed=1; }
run "$P" pzAevnQ --preallocate            # attributes, markers, regions' attributes, edges, Voronoi, neighbours, from 0
run "$P" pq30aAen                         # quality, regional area bounds (a bare a), from 1
run "$P" pcjo2eBQ --preallocate           # convex hull, jettison, second order, no markers
run "$P" pDq25YeQ                         # conforming Delaunay, no boundary Steiner points
run "$P" pYYq20Q
run "$P" pS20qeQ                          # a Steiner point limit
run "$P" pa0.05PNEeQ                      # no .poly, .node, .ele: edges only
run "$P" pVCQ                             # the check, verbose (the library prints nothing)
run "$P" pqAQ rpq30a0.02eAQ --preallocate # r: the first output refined again, as a caller would
run "$P" pzqQ rpzq25a0.05nQ
run "$D/guitar.poly" pq28evnQ
run "$D/ukraine.node" ievQ                # incremental, a point set's Voronoi with rays
run "$D/ukraine.node" lzenQ               # vertical cuts
run "$D/ukraine.node" q30u20eQ            # an edge-length bound
run "$D/robustness2.node" jzevQ           # duplicates left out by j
run "$E/sq_attr.node" vzQ                 # Voronoi vertex attributes
# r with a bare a: a previous mesh as files (.node, .ele with attributes, .area with some bounds
# and some -1), read by the command line as named and by the client as trianglelist,
# triangleattributelist and trianglearealist.
mkdir "$work/previous" && cp "$P" "$work/previous/" && (cd "$work/previous" && "$build/deltri" -pqAQ plate_attr.poly) &&
  awk 'NR == 1 { print $1; n = $1; next } NF && $1 !~ /^#/ { print $1, ($1 % 3 == 0 ? -1 : 0.002 * ($1 % 7 + 1)) }' \
      "$work/previous/plate_attr.1.ele" >"$work/previous/plate_attr.1.area" || { echo "FAIL: making the previous mesh"; failed=1; }
run "$work/previous/plate_attr.1.ele" raAeQ --preallocate   # per-triangle area bounds (trianglearealist)
run "$work/previous/plate_attr.1.ele" rqa0.05zQ             # numbered from 0
[ $failed = 0 ] && echo "the installed C library agrees with the command line on every case"
exit $failed
