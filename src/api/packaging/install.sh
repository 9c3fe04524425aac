#!/bin/sh
# `make install` and `make uninstall` (Makefile; README.md, docs/library.md):
#   install.sh install BUILD_DIR DESTDIR PREFIX
#   install.sh uninstall DESTDIR PREFIX
# install runs CMake's install rules, writes the folders it created (and only those) into
# PREFIX/lib/cmake/deltri/deltri-install-folders.txt, and runs ldconfig where the dynamic linker's
# cache is what finds the library: no DESTDIR, PREFIX /usr or /usr/local, as root. uninstall removes
# the files install put there and then those folders where they are empty (deepest first), so a
# folder that existed before, or that now holds something else, stays.
set -u
RECORD=lib/cmake/deltri/deltri-install-folders.txt

absolute() {  # a relative PREFIX is taken from the folder make runs in
  case $1 in /*) printf '%s\n' "${1%/}" ;; *) printf '%s/%s\n' "$(pwd)" "${1%/}" ;; esac
}

system_prefix() {  # DESTDIR PREFIX: true where ldconfig's cache is what finds PREFIX/lib
  [ -z "$1" ] && [ "$(id -u)" = 0 ] && { [ "$2" = /usr ] || [ "$2" = /usr/local ]; }
}

refresh_linker_cache() {  # DESTDIR PREFIX
  if system_prefix "$1" "$2"; then
    command -v ldconfig >/dev/null 2>&1 && ldconfig || echo "deltri: run ldconfig as root so that programs find libdeltri.so.0"
  elif [ -z "$1" ] && { [ "$2" = /usr ] || [ "$2" = /usr/local ]; }; then
    echo "deltri: run 'sudo ldconfig' so that programs find $2/lib/libdeltri.so.0"
  fi
}

install() {  # BUILD DESTDIR PREFIX
  build=$1 dest=$2 prefix=$(absolute "$3")
  stage=$(mktemp -d) || exit 1
  trap 'rm -rf "$stage"' EXIT
  # The folders the install rules make, found by installing into a scratch folder first.
  DESTDIR=$stage cmake --install "$build" --prefix "$prefix" >/dev/null || exit 1
  new=$(cd "$stage" && find . -mindepth 1 -type d | sed 's,^\.,,' | while read -r d; do
          [ -d "$dest$d" ] || printf '%s\n' "$d"; done)
  DESTDIR=$dest cmake --install "$build" --prefix "$prefix" || exit 1
  record=$dest$prefix/$RECORD
  # A second install keeps the first one's list: those folders are still the install's own.
  { [ -f "$record" ] && cat "$record"; [ -n "$new" ] && printf '%s\n' "$new"; } | LC_ALL=C sort -u >"$stage/list"
  cp "$stage/list" "$record"
  refresh_linker_cache "$dest" "$prefix"
}

uninstall() {  # DESTDIR PREFIX
  dest=$1 prefix=$(absolute "$2")
  root=$dest$prefix
  folders=
  [ -f "$root/$RECORD" ] && folders=$(LC_ALL=C sort -r "$root/$RECORD")
  rm -f "$root/bin/deltri" "$root/share/man/man1/deltri.1" "$root/lib/pkgconfig/deltri.pc"
  rm -f "$root"/lib/libdeltri.so "$root"/lib/libdeltri.so.* "$root/lib/libdeltri.a"
  rm -rf "$root/include/deltri" "$root/lib/cmake/deltri" "$root"/lib/python3*/dist-packages/deltri
  # sort -r puts a folder after everything inside it.
  printf '%s\n' "$folders" | while read -r d; do
    [ -n "$d" ] && [ -d "$dest$d" ] && rmdir "$dest$d" 2>/dev/null
  done
  refresh_linker_cache "$dest" "$prefix"
  return 0
}

case ${1:-} in
  install) shift; install "$@" ;;
  uninstall) shift; uninstall "$@" ;;
  *) echo "usage: install.sh install BUILD DESTDIR PREFIX | uninstall DESTDIR PREFIX" >&2; exit 2 ;;
esac
