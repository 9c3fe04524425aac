#!/bin/sh
# The warning's count of triangles that miss the bounds is the final mesh's (issue 47, item 12):
# it was the refinement queue's count, 2264 where eberly-6.poly's -pq38 mesh has 2269 triangles
# under 38 degrees (3519 against 3527 at -pq42). The count in the warning must lie between the
# numbers of output triangles whose smallest angle, computed here from the .node and .ele, is
# below the bound minus and plus 1e-6 degrees (count_angles.awk). -pq38 has been met since the second
# stage moves free vertices (docs/refinement.md, "-q40 and above"), so -pq42 and -pq44 are checked.
#   miss-count.sh DELTRI VERIFY
here=$(cd "$(dirname "$0")" && pwd)
. "$here/lib.sh"
cp "$here/../../../data/eberly-6.poly" .
for q in 42 44; do
  ends_counted eberly-6.poly eberly-6.1 -pq$q eberly-6.poly
  said=$(sed -n 's/.*: \([0-9]*\) triangles miss the requested bounds.*/\1/p' stderr.last)
  set -- $(awk -v q="$q" -v eps=1e-6 -f "$here/count_angles.awk" eberly-6.1.node eberly-6.1.ele)
  echo "-pq$q: the warning says $said; triangles below $q degrees: $1 to $2"
  [ -n "$said" ] && [ "$said" -ge "$1" ] && [ "$said" -le "$2" ] || fail "-pq$q: the warning's count is not the mesh's"
done
echo "ok"
