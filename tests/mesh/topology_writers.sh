#!/bin/sh
# The topology kernel's fence (issue 20): only src/mesh/ (and the divide-and-conquer builder, which
# keeps raw arrays in its own file) may write triangle corners, links and subsegment flags, and
# only src/mesh/ may spell out slot arithmetic like 3 * t + i, e / 3 or e % 3 (the ids are strong
# types, src/mesh/ids.h, but they convert to integers for indexing, so the compiler alone does not
# stop it). Writes outside the kernel no longer compile either (Mesh's topology arrays are
# TopologyArrays, written through mesh/topology_writer.h), so the grep also flags that header and
# its corner_slots / link_slots / subseg_slots. Every stage is on the kernel now; the one file
# listed below is the divide-and-conquer builder, whose raw arrays spell out slot arithmetic by
# design (its Builder class, docs/architecture.md), with its count of such lines: the test fails
# when a file not listed does it, or the listed file does it more often.
# usage: topology_writers.sh SOURCE_DIR
cd "$1/src" || exit 2
WRITE='(\b(corner|link|subseg)\[[^]]*\][[:space:]]*=[^=])|(\.(bond|set_subsegment|kill_triangle|add_triangle|append_triangle)\()|(\b(corner|link|subseg)\.(resize|assign|push_back|swap)\()|(\b(corner|link|subseg)_slots\()|(mesh/topology_writer\.h)'
# Slot arithmetic on ids: 3 * t (+ i), e / 3 (the triangle), e % 3 (the side). mesh/ids.h names
# these (edge_of, triangle_of, side_of, lnext, lprev); `(i + 1) % 3` on a corner number and
# divisions by 3.0 do not match.
INDEX='(\b3 \* [a-z_])|(\b[a-z_][a-z_0-9]* % 3\b)|(\b[a-z_][a-z_0-9]* / 3([^.0-9]|$))'
allowed() {  # kind file -> the listed count, or 0
  sed -n "s|^$1 $2 ||p" <<'LIST' | head -n 1
index delaunay/divide_and_conquer.cpp 5
LIST
}
check() {  # kind pattern exempt-regex
  grep -rncE "$2" --include=*.cpp --include=*.h . | sed 's|^\./||' | grep -v ':0$' | grep -vE "$3" |
    while IFS=: read -r file count; do
      limit=$(allowed "$1" "$file"); limit=${limit:-0}
      if [ "$count" -gt "$limit" ]; then
        echo "$file: $count lines of $1 outside the kernel (allowed $limit)"
        grep -nE "$2" "$file" | head -n 5
      fi
    done
}
out=$( { check write "$WRITE" '^(mesh/|delaunay/divide_and_conquer\.cpp:)'; check index "$INDEX" '^mesh/'; } )
if [ -n "$out" ]; then
  echo "$out"
  exit 1
fi
echo "no topology writes or slot arithmetic outside src/mesh/ beyond the listed files"
