#!/bin/sh
# Triangle's C users (issue 46): `make install` into a scratch DESTDIR (PREFIX /usr/local), then a
# client that says #include "triangle.h" (tests/setup/triangle_h_client.c) compiled with nothing but
# `cc client.c $(pkg-config --cflags --libs deltri)`, PKG_CONFIG_PATH pointing into DESTDIR. It runs
# with LD_LIBRARY_PATH there (ldconfig is for a real system prefix only) and its meshes must cover
# the unit square: 4 triangles first (2n - 2 - h for 5 points, 4 on the hull), areas summing to 1,
# none above 0.01 after the refinement. Then `make uninstall` must leave DESTDIR as it was, empty.
#   c_users_test.sh SOURCE_DIR BUILD_DIR [SANITIZER_FLAGS]
# (SANITIZER_FLAGS: a sanitizer build's library needs their runtime in the client as well.)
set -u
unset MAKEFLAGS MFLAGS MAKELEVEL MAKEOVERRIDES GNUMAKEFLAGS
src=$1 build=$2 sanitize=${3:-}
command -v pkg-config >/dev/null && command -v cc >/dev/null ||
  { echo "SKIP: missing pkg-config or cc; install with: sudo apt-get install -y pkg-config gcc"; exit 77; }
work=$(mktemp -d) || exit 1
trap 'rm -rf "$work"' EXIT
failed=0
fail() { echo "FAIL: $*"; failed=1; }
mkdir "$work/dest"
make -s -C "$src" install BUILD="$build" DESTDIR="$work/dest" >"$work/log" 2>&1 || { cat "$work/log"; echo "FAIL: make install"; exit 1; }
root=$work/dest/usr/local
export PKG_CONFIG_PATH="$root/lib/pkgconfig"
cflags=$(pkg-config --cflags deltri)
found=
for flag in $cflags; do
  case $flag in -I*) [ "$(cd "${flag#-I}" 2>/dev/null && pwd -P)" = "$(cd "$root/include/deltri" && pwd -P)" ] && found=1 ;; esac
done
[ -n "$found" ] || fail "pkg-config --cflags deltri gives '$cflags', without $root/include/deltri"
cp "$src/tests/setup/triangle_h_client.c" "$work/client.c"
(cd "$work" && cc $sanitize client.c $(pkg-config --cflags --libs deltri) -o client) >"$work/log" 2>&1 ||
  fail "cc client.c \$(pkg-config --cflags --libs deltri): $(cat "$work/log")"
# <deltri/triangle.h> still works as well.
printf '#include <deltri/triangle.h>\nint main(void) { trifree(0); return 0; }\n' >"$work/old.c"
(cd "$work" && cc $sanitize old.c $(pkg-config --cflags --libs deltri) -o old) >"$work/log" 2>&1 || fail "#include <deltri/triangle.h>: $(cat "$work/log")"
if [ -x "$work/client" ]; then
  out=$(LD_LIBRARY_PATH="$root/lib" "$work/client") || fail "the client failed: $out"
  echo "$out"
  echo "$out" | awk '
    $1 == "first" { first = ($2 == 4 && $3 > 1 - 1e-12 && $3 < 1 + 1e-12) }
    $1 == "refined" { refined = ($2 >= 100 && $3 > 1 - 1e-12 && $3 < 1 + 1e-12 && $4 <= 0.01) }
    END { exit !(first && refined) }' || fail "the client's meshes do not cover the unit square as asked: $out"
fi
make -s -C "$src" uninstall DESTDIR="$work/dest" >"$work/log" 2>&1 || fail "make uninstall: $(cat "$work/log")"
left=$(cd "$work/dest" && find . | LC_ALL=C sort | tr '\n' ' ')
[ "$left" = ". " ] || fail "left in DESTDIR after uninstall: $left"
[ $failed = 0 ] && echo "a client with #include \"triangle.h\" builds with pkg-config's flags alone and meshes the square; uninstall leaves nothing"
exit $failed
