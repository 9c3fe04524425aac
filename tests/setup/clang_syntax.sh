#!/bin/sh
# The sources compile with clang too (Debian's clang 14), not only with g++: the fuzz build and
# users who build with clang need it, and it broke twice unnoticed (a structured binding captured
# by a lambda, which clang accepts only from version 16). Every source of the program and the
# library, and the fuzz targets, checked with -fsyntax-only and the project's warnings as errors.
# Exits 77 (skipped) where clang++ is not installed (tests/setup/install_test_deps.sh installs it).
#   clang_syntax.sh SOURCE_DIR
set -u
root=$1
command -v clang++ >/dev/null 2>&1 || { echo "clang++ not installed: skipped"; exit 77; }
files=$(find "$root/src" "$root/tests/fuzz" -name '*.cpp' | LC_ALL=C sort)
count=$(echo "$files" | wc -l)
# Two at a time: the suite runs beside it.
if echo "$files" | xargs -P 2 -n 12 clang++ -std=c++20 -fsyntax-only -Wall -Wextra -Werror \
    -DDELTRI_VERSION=\"syntax-check\" -I"$root/src" -I"$root/src/api" -I"$root/tests/fuzz"; then
  echo "clang++ -fsyntax-only: $count sources, no error"
else
  echo "clang++ rejects a source (above)"
  exit 1
fi
