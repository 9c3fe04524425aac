#!/bin/sh
# The test readers and solvers that some tests run (formats.*, the solver tests): installed once by
# `make test` before CTest, so that the README's two commands are the whole set-up on Debian.
#   install_test_deps.sh [STATE]         check each; install the missing ones with apt-get (as root,
#                                        or through sudo when it needs no password); say what it
#                                        does; write what is still missing into the file STATE
#   install_test_deps.sh --hint [STATE]  only say what is still missing (as STATE says, else as
#                                        checked now) and the command that installs it
# A package already there costs one quick check (command -v, a Python import, dpkg-query), so a
# second run does nothing. Where installing is not possible the tests that need the package exit
# 77 and CTest reports them as skipped; the rest still run. DELTRI_NO_INSTALL=1 never installs.
# Always exits 0: a missing reader is a skipped test, not a failed set-up.
PY=/usr/bin/python3

# package|how to tell it is there
PACKAGES='python3-meshio|py:meshio
python3-numpy|py:numpy
python3-matplotlib|py:matplotlib
pkg-config|cmd:pkg-config
binutils|cmd:objdump
gmsh|cmd:gmsh
librsvg2-bin|cmd:rsvg-convert
getdp|cmd:getdp
freefem++|cmd:FreeFem++
libfreefem++|deb:libfreefem++
clang|cmd:clang++'

present() {
  case $1 in
    py:*) [ -x "$PY" ] && "$PY" -c "import ${1#py:}" 2>/dev/null ;;
    cmd:*) command -v "${1#cmd:}" >/dev/null 2>&1 ;;
    deb:*) dpkg-query -W -f='${Status}' "${1#deb:}" 2>/dev/null | grep -q 'install ok installed' ;;
  esac
}

missing() {
  echo "$PACKAGES" | while IFS='|' read -r package test; do
    present "$test" || printf '%s ' "$package"
  done
}

if [ "${1:-}" = --hint ]; then
  if [ -n "${2:-}" ] && [ -f "$2" ]; then todo=$(cat "$2"); else todo=$(missing); fi
  todo=${todo% }
  [ -z "$todo" ] || echo "tests: skipped where these are missing: $todo; install them with: sudo apt-get install -y $todo"
  exit 0
fi
state=${1:-/dev/null}
todo=$(missing)
todo=${todo% }
echo "$todo" >"$state"
if [ -z "$todo" ]; then
  exit 0
fi

as_root=
if [ "$(id -u)" = 0 ]; then
  as_root=
elif command -v sudo >/dev/null 2>&1 && sudo -n true 2>/dev/null; then
  as_root="sudo -n"
else
  as_root=none
fi
if [ "${DELTRI_NO_INSTALL:-}" = 1 ] || [ "$as_root" = none ] || ! command -v apt-get >/dev/null 2>&1; then
  echo "tests: not installed (no root, no password-less sudo, no apt-get, or DELTRI_NO_INSTALL=1): $todo"
  echo "tests: the tests that need them will be skipped; to run them: sudo apt-get install -y $todo"
  exit 0
fi

echo "tests: installing the test readers and solvers: apt-get install -y $todo"
export DEBIAN_FRONTEND=noninteractive
apt_install() {
  # shellcheck disable=SC2086  # $todo is a list of package names
  $as_root apt-get install -y -q -o DPkg::Lock::Timeout=300 --no-install-recommends $todo >"$log" 2>&1
}
log=$(mktemp) || exit 0
# A fresh machine may have no package lists yet: then update once and try again.
if ! apt_install; then
  echo "tests: apt-get install failed; running apt-get update first"
  $as_root apt-get update -q -o DPkg::Lock::Timeout=300 >>"$log" 2>&1
  apt_install
fi
left=$(missing)
left=${left% }
echo "$left" >"$state"
if [ -n "$left" ]; then
  tail -n 5 "$log"
  echo "tests: still missing: $left; the tests that need them will be skipped (sudo apt-get install -y $left)"
else
  echo "tests: installed $todo"
fi
rm -f "$log"
exit 0
