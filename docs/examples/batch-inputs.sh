#!/bin/sh
# Which .poly files in the current folder are inputs to mesh, told from deltri's outputs by what
# deltri wrote, not by their names: every run of the batch recipes writes a JSON report
# (name.poly.json, deltri --json=...) whose "files" list names each file that run wrote.
#   sh batch-inputs.sh            the inputs, one a line (for xargs -I and batch.mk)
#   sh batch-inputs.sh --outputs  the files the reports say deltri wrote, reports included (clean)
# A .poly no report lists is an input, whatever its name: box.1.poly shipped beside box.poly (a
# Triangle output kept as an input) is one. Meshing box.poly would write box.1.poly over it, so
# box.poly is then left out, with a line on standard error; rename one of the two to mesh both.
# Assumes file names without newlines.

reports() {
  for r in *.poly.json; do
    [ -f "$r" ] && head -c 19 "$r" | grep -q '^{"program":"deltri"' && printf '%s\n' "$r"
  done
}

# The "files" of every report, one a line (deltri writes the list last, on the report's one line).
outputs() {
  reports | while IFS= read -r r; do
    sed -n 's/.*"files":\[\(.*\)\]}$/\1/p' "$r" | sed 's/","/\n/g; s/^"//; s/"$//'
  done
}

# Triangle's output name for an input: box.poly -> box.1, box.1.poly -> box.2.
output_base() {
  base=${1%.poly}
  n=${base##*.}
  case $n in
    "$base" | "" | *[!0-9]*) printf '%s.1\n' "$base" ;;
    *) printf '%s.%s\n' "${base%.*}" "$(expr "$n" + 1)" ;;
  esac
}

if [ "${1:-}" = --outputs ]; then
  outputs | while IFS= read -r f; do [ -e "$f" ] && printf '%s\n' "$f"; done
  exit 0
fi

written=$(outputs)
is_output() { printf '%s\n' "$written" | grep -Fxq -- "$1"; }
for f in *.poly; do
  [ -f "$f" ] || continue
  is_output "$f" && continue
  out=$(output_base "$f")
  clash=
  for o in "$out.node" "$out.ele" "$out.poly"; do
    [ -e "$o" ] && ! is_output "$o" && clash=$o && break
  done
  if [ -n "$clash" ]; then
    echo "batch-inputs.sh: $f not meshed: deltri would write $clash over an input here (rename one of them)" >&2
    continue
  fi
  printf '%s\n' "$f"
done
