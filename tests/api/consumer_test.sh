#!/bin/sh
# A CMake project that finds the installed deltri (find_package(deltri REQUIRED)) and links
# deltri::deltri and deltri::deltri_static (tests/api/consumer), built and run; one program says
# #include "triangle.h" as Triangle's C users do (tests/setup/triangle_h_client.c).
#   consumer_test.sh SOURCE_DIR BUILD_DIR [SANITIZER_FLAGS]
set -u
unset MAKEFLAGS MFLAGS MAKELEVEL
src=$1 build=$2 sanitize=${3:-}
work=$(mktemp -d) || exit 1
trap 'rm -rf "$work"' EXIT
cmake --install "$build" --prefix "$work/prefix" >"$work/log" 2>&1 || { cat "$work/log"; echo "FAIL: cmake --install"; exit 1; }
cmake -S "$src/tests/api/consumer" -B "$work/consumer" -DCMAKE_PREFIX_PATH="$work/prefix" -DCMAKE_BUILD_TYPE=Release \
      -DCMAKE_CXX_FLAGS="$sanitize" -DCMAKE_C_FLAGS="$sanitize" >"$work/log" 2>&1 || { cat "$work/log"; echo "FAIL: find_package(deltri)"; exit 1; }
cmake --build "$work/consumer" -j 2 >"$work/log" 2>&1 || { cat "$work/log"; echo "FAIL: the consumer does not build"; exit 1; }
failed=0
for program in consumer_shared consumer_static consumer_c consumer_triangle_h; do
  "$work/consumer/$program" || { echo "FAIL: $program"; failed=1; }
done
ldd "$work/consumer/consumer_shared" | grep -q "$work/prefix/lib/libdeltri.so.0" || { echo "FAIL: consumer_shared does not use the installed libdeltri.so.0 (rpath)"; failed=1; }
[ $failed = 0 ] && echo "find_package(deltri): deltri::deltri and deltri::deltri_static link and run, #include \"triangle.h\" included"
exit $failed
