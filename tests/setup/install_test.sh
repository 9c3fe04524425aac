#!/bin/sh
# `make install` and `make uninstall` (Makefile, CMake's install rules) into scratch folders:
#   install_test.sh SOURCE_DIR BUILD_DIR
# 1. PREFIX=<tmp>/prefix; 2. DESTDIR=<tmp>/dest with the default PREFIX (/usr/local). Each time the
# installed deltri must run (its --version equals the build's; it meshes data/box.poly), the man
# page must be docs/deltri.1, the library files must be there (tests/api checks that they work), and
# uninstall must remove every file and every folder install created, and nothing else: a folder that
# was there before (here PREFIX/lib with a file of its own, and DESTDIR) stays.
set -u
# How the surrounding make was called must not matter here.
unset MAKEFLAGS MFLAGS MAKELEVEL MAKEOVERRIDES GNUMAKEFLAGS
src=$1 build=$2
work=$(mktemp -d) || exit 1
trap 'rm -rf "$work"' EXIT
failed=0
fail() { echo "FAIL: $*"; failed=1; }

check_installed() {  # ROOT: the folder bin/ and share/ are in
  root=$1
  [ -x "$root/bin/deltri" ] || { fail "$root/bin/deltri missing"; return; }
  [ "$("$root/bin/deltri" --version)" = "$("$build/deltri" --version)" ] || fail "the installed deltri's --version differs"
  cmp -s "$root/share/man/man1/deltri.1" "$src/docs/deltri.1" || fail "$root/share/man/man1/deltri.1 is not docs/deltri.1"
  mkdir -p "$work/run" && cp "$src/data/box.poly" "$work/run/"
  (cd "$work/run" && "$root/bin/deltri" -pq30Q box.poly) || fail "the installed deltri could not mesh box.poly"
  [ -s "$work/run/box.1.ele" ] || fail "the installed deltri wrote no box.1.ele"
  rm -rf "$work/run"
}
files() { (cd "$1" && find . -type f | LC_ALL=C sort | tr '\n' ' '); }

make -s -C "$src" install BUILD="$build" PREFIX="$work/prefix" >"$work/log" 2>&1 || fail "make install PREFIX=...: $(cat "$work/log")"
check_installed "$work/prefix"
expected="./bin/deltri ./include/deltri/deltri.hpp ./include/deltri/triangle.h ./lib/cmake/deltri/deltri-install-folders.txt ./lib/cmake/deltri/deltriConfig.cmake \
./lib/cmake/deltri/deltriConfigVersion.cmake ./lib/cmake/deltri/deltriTargets-release.cmake ./lib/cmake/deltri/deltriTargets.cmake \
./lib/libdeltri.a ./lib/libdeltri.so.0.9.0 ./lib/pkgconfig/deltri.pc ./lib/python3.N/dist-packages/deltri/__init__.py ./share/man/man1/deltri.1 "
installed=$(files "$work/prefix" | sed 's,/python3\.[0-9]*/,/python3.N/,; s,deltriTargets-[a-z]*\.cmake,deltriTargets-release.cmake,')
version=$("$build/deltri" --version | sed 's/deltri //')
[ "$installed" = "$(echo "$expected" | sed "s/0\.9\.0/$version/")" ] || fail "installed: $installed"
[ "$(readlink "$work/prefix/lib/libdeltri.so")" = libdeltri.so.0 ] && [ "$(readlink "$work/prefix/lib/libdeltri.so.0")" = "libdeltri.so.$version" ] ||
  fail "the libdeltri.so -> libdeltri.so.0 -> libdeltri.so.$version links are missing"
make -s -C "$src" uninstall PREFIX="$work/prefix" >"$work/log" 2>&1 || fail "make uninstall PREFIX=...: $(cat "$work/log")"
[ ! -e "$work/prefix" ] || fail "left after uninstall: $(cd "$work/prefix" && find . | LC_ALL=C sort | tr '\n' ' ')"

# A folder that was there before install stays, with what it holds; a second install over the first
# keeps the first one's list of created folders.
mkdir -p "$work/prefix2/lib" && echo mine >"$work/prefix2/lib/other.txt"
for i in 1 2; do
  make -s -C "$src" install BUILD="$build" PREFIX="$work/prefix2" >"$work/log" 2>&1 || fail "make install PREFIX=... ($i): $(cat "$work/log")"
done
make -s -C "$src" uninstall PREFIX="$work/prefix2" >"$work/log" 2>&1 || fail "make uninstall PREFIX=... (twice installed): $(cat "$work/log")"
left=$(cd "$work/prefix2" && find . | LC_ALL=C sort | tr '\n' ' ')
[ "$left" = ". ./lib ./lib/other.txt " ] || fail "after two installs and one uninstall into a PREFIX with lib/other.txt: $left"

mkdir "$work/dest"
make -s -C "$src" install BUILD="$build" DESTDIR="$work/dest" >"$work/log" 2>&1 || fail "make install DESTDIR=...: $(cat "$work/log")"
check_installed "$work/dest/usr/local"
make -s -C "$src" uninstall DESTDIR="$work/dest" >"$work/log" 2>&1 || fail "make uninstall DESTDIR=...: $(cat "$work/log")"
left=$(cd "$work/dest" && find . | LC_ALL=C sort | tr '\n' ' ')
[ "$left" = ". " ] || fail "left in DESTDIR after uninstall: $left"

[ $failed = 0 ] && echo "install: deltri in PREFIX/bin and deltri.1 in PREFIX/share/man/man1, the libraries, headers, CMake package, pkg-config file and Python module (PREFIX=... and DESTDIR=...); deltri runs, the man page matches, uninstall removes them and the folders install made, and only those"
exit $failed
