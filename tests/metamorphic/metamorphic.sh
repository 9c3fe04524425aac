#!/bin/sh
# Metamorphic tests (called by CTest, see CMakeLists.txt in this directory):
#   metamorphic.sh DELTRI VERIFY KIND INPUT SWITCHES
# KIND scale:K      multiply every coordinate by 2^K (exact in binary floating point)
#      translate:K  add 2^K to every coordinate (exact for the lattice inputs used with it)
#      permute:SEED shuffle the vertices (segments renumbered to match)
# INPUT is a .node/.poly file or gen:star.poly (a star-shaped polygon with a star-shaped hole and
# free vertices between, coordinates on a 2^-10 lattice in (-1, 1)), gen:star5.poly (the same
# centred at (5, 5): coordinates in [4, 6)) or gen:random.poly (the star with random doubles: in
# general position).
# scale and translate: every decision of the algorithm is the same on the transformed input, so
# the triangles by vertex number must be the same set, and (with refinement) so must the vertex
# count. With refinement a translation must keep every coordinate in its binade ([4, 6) + 2 lies
# in [4, 8)): new vertices are rounded to the spacing of the doubles where they fall, and that
# spacing must not change. permute: on an input in general position the Delaunay/constrained Delaunay
# triangulation is unique, so mapping the triangles back through the permutation must give the
# same set; the mesh must also pass the verifier.
set -u
deltri=$1 verify=$2 kind=$3 input=$4 switches=$5
[ "$switches" = none ] && switches=
work=$(mktemp -d) || exit 1
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

gen() {  # gen NAME FILE
  awk -v lattice="$([ "$1" = random.poly ] && echo 0 || echo 1)" -v centre="$([ "$1" = star5.poly ] && echo 5 || echo 0)" 'BEGIN {
    srand(7); pi = atan2(0, -1); m = 40; h = 12; f = 60
    print m + h + f, 2, 0, 0
    n = 0
    for (k = 0; k < m; k++) { r = 0.85 + 0.15 * rand(); a = 2 * pi * (k + 0.3 * rand()) / m; pt(r * cos(a), r * sin(a)) }
    for (k = 0; k < h; k++) { r = 0.15 + 0.05 * rand(); a = 2 * pi * (k + 0.3 * rand()) / h; pt(r * cos(a), r * sin(a)) }
    for (k = 0; k < f; k++) { r = 0.3 + 0.5 * rand(); a = 2 * pi * rand(); pt(r * cos(a), r * sin(a)) }
    print m + h, 0
    for (k = 0; k < m; k++) print k + 1, k + 1, (k + 1) % m + 1
    for (k = 0; k < h; k++) print m + k + 1, m + k + 1, m + (k + 1) % h + 1
    print 1; print 1, centre, centre
  }
  function pt(x, y) {
    if (lattice) { x = int(x * 1024) / 1024; y = int(y * 1024) / 1024 }
    printf "%d %.17g %.17g\n", ++n, x + centre, y + centre
  }' >"$2"
}

case $input in
  gen:*) name=${input#gen:}; gen "$name" "$work/orig.${name##*.}" ;;
  *) name=$(basename "$input"); cp "$input" "$work/orig.${name##*.}" ;;
esac
ext=${name##*.}

# The transformed copy, written by one awk pass over the format (comments and blank lines
# dropped): vertex, hole and region coordinates change; with scale, region area bounds by 4^K.
transform() {  # transform MODE PARAM IN OUT [PERMFILE]
  awk -v mode="$1" -v param="$2" -v ext="$ext" -v permfile="${5:-}" '
  function coord(v) { return mode == "scale" ? v * factor : v + offset }
  BEGIN { factor = 2 ^ param; offset = 2 ^ param; srand(param + 0) }
  { sub(/#.*/, ""); if (NF == 0) next; line[++L] = $0 }
  END {
    i = 1; split(line[i++], hd); nv = hd[1]
    print line[1]
    for (k = 1; k <= nv; k++) { rec[k] = line[i++] }
    if (mode == "permute") {
      for (k = 1; k <= nv; k++) p[k] = k
      for (k = nv; k > 1; k--) { j = int(rand() * k) + 1; t = p[k]; p[k] = p[j]; p[j] = t }
      # new vertex k is old vertex p[k]; q is the inverse
      for (k = 1; k <= nv; k++) q[p[k]] = k
      split(rec[1], f1); first = f1[1]
      for (k = 1; k <= nv; k++) {
        split(rec[p[k]], f); out = (k - 1 + first)
        for (c = 2; c <= length(f); c++) out = out " " f[c]
        print out; print k - 1 + first, p[k] - 1 + first >permfile
      }
    } else {
      for (k = 1; k <= nv; k++) { n = split(rec[k], f); out = f[1] " " sprintf("%.17g %.17g", coord(f[2]), coord(f[3]))
        for (c = 4; c <= n; c++) out = out " " f[c]; print out }
    }
    if (ext != "poly") exit
    split(line[i], sh); ns = sh[1]; print line[i++]
    for (k = 1; k <= ns; k++) { n = split(line[i++], f)
      if (mode == "permute") { f[2] = q[f[2] - first + 1] - 1 + first; f[3] = q[f[3] - first + 1] - 1 + first }
      out = f[1]; for (c = 2; c <= n; c++) out = out " " f[c]; print out }
    nh = line[i] + 0; print line[i++]
    for (k = 1; k <= nh; k++) { n = split(line[i++], f)
      if (mode != "permute") { f[2] = sprintf("%.17g", coord(f[2])); f[3] = sprintf("%.17g", coord(f[3])) }
      out = f[1]; for (c = 2; c <= n; c++) out = out " " f[c]; print out }
    if (i > L) exit
    nr = line[i] + 0; print line[i++]
    for (k = 1; k <= nr; k++) { n = split(line[i++], f)
      if (mode != "permute") { f[2] = sprintf("%.17g", coord(f[2])); f[3] = sprintf("%.17g", coord(f[3])) }
      if (mode == "scale" && n >= 5) f[5] = sprintf("%.17g", f[5] * factor * factor)
      out = f[1]; for (c = 2; c <= n; c++) out = out " " f[c]; print out }
  }' "$3" >"$4"
}

# Triangles as "a b c" with the smallest number first (orientation kept), one per line, sorted;
# with a permutation file, numbers are first mapped back to the original vertices.
triangles() {  # triangles ELE [PERMFILE]
  awk -v permfile="${2:-}" '
  BEGIN { if (permfile != "") while ((getline l <permfile) > 0) { split(l, f); back[f[1]] = f[2] } }
  { sub(/#.*/, "") } NF == 0 { next }
  !header { header = 1; next }
  { a = $2; b = $3; c = $4
    if (permfile != "") { a = back[a]; b = back[b]; c = back[c] }
    if (b + 0 < a + 0 && b + 0 < c + 0) { t = a; a = b; b = c; c = t }
    else if (c + 0 < a + 0 && c + 0 < b + 0) { t = c; c = b; b = a; a = t }
    print a, b, c }' "$1" | LC_ALL=C sort
}

mode=${kind%%:*} param=${kind#*:}
cp "$work/orig.$ext" "$work/input.$ext"
transform "$mode" "$param" "$work/orig.$ext" "$work/changed.$ext" "$work/perm"
for run in input changed; do
  (cd "$work" && "$deltri" $switches -Q "$run.$ext") || fail "deltri $switches $run.$ext failed"
done
[ -s "$work/changed.1.ele" ] || fail "no mesh"
orig_tris=$(triangles "$work/input.1.ele" | tee "$work/t1" | wc -l)
if [ "$mode" = permute ]; then
  triangles "$work/changed.1.ele" "$work/perm" >"$work/t2"
  case $ext in node) vopt=--convex-hull ;; *) vopt= ;; esac
  (cd "$work" && "$verify" --input "changed.$ext" --mesh changed.1 $vopt) || fail "the permuted input's mesh fails the verifier"
else
  triangles "$work/changed.1.ele" >"$work/t2"
  n1=$(awk '!/^#/ && NF { print $1; exit }' "$work/input.1.node")
  n2=$(awk '!/^#/ && NF { print $1; exit }' "$work/changed.1.node")
  [ "$n1" = "$n2" ] || fail "vertex count $n1 became $n2"
fi
new_tris=$(wc -l <"$work/t2")
echo "$name $switches $kind: $orig_tris triangles, then $new_tris"
[ "$orig_tris" -gt 0 ] || fail "the original mesh has no triangles"
[ "$orig_tris" = "$new_tris" ] || fail "triangle count $orig_tris became $new_tris"
cmp -s "$work/t1" "$work/t2" || fail "the triangles differ ($(comm -3 "$work/t1" "$work/t2" | wc -l) lines)"
exit 0
