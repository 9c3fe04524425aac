#!/bin/sh
# --smooth end to end (docs/refinement.md, "Mesh improvement (--smooth)"), on data/ samples and
# generated polygons: each is meshed without and with the pass; with it, -C must pass, the output
# must be the same for --threads=1 and --threads=2, deltri_mesh_verify must find the mesh sound and
# meeting its -q/-a bounds, and from the files alone (awk, atan2) the triangle count must be the
# same, the smallest angle not lower and the mean smallest angle not lower (higher over the sample).
# usage: smooth.sh DELTRI VERIFY DATA_DIR E2E_INPUTS
set -u
deltri=$1 verify=$2 data=$3 inputs=$4
work=$(mktemp -d) || exit 1
trap 'rm -rf "$work"' EXIT
failed=0
fail() { echo "FAIL: $*"; failed=1; }

# A star-shaped polygon of $2 corners at pseudo-random radii (seed $1).
polygon() {
  awk -v seed="$1" -v n="$2" 'BEGIN { s = seed; pi = 3.14159265358979
    print n, 2, 0, 0
    for (i = 1; i <= n; i++) { s = (s * 16807) % 2147483647; r = 0.4 + 0.6 * s / 2147483647
      a = 2 * pi * (i - 1) / n; printf "%d %.17g %.17g\n", i, r * cos(a), r * sin(a) }
    print n, 0
    for (i = 1; i <= n; i++) print i, i, i % n + 1
    print 0 }'
}

# Triangles, smallest angle and sum of smallest angles per triangle of BASE.node/.ele.
figures() {
  awk 'FNR == 1 { file++; next } /^#/ || NF == 0 { next }
    file == 1 { x[$1] = $2; y[$1] = $3; next }
    file == 2 { s = 180; for (k = 0; k < 3; k++) {
        a = $(2 + k); b = $(2 + (k + 1) % 3); c = $(2 + (k + 2) % 3)
        ux = x[b] - x[a]; uy = y[b] - y[a]; vx = x[c] - x[a]; vy = y[c] - y[a]
        cr = ux * vy - uy * vx; if (cr < 0) cr = -cr
        t = atan2(cr, ux * vx + uy * vy) * 57.295779513082321; if (t < s) s = t }
      n++; sum += s; if (n == 1 || s < least) least = s }
    END { printf "%d %.12f %.12f\n", n, least, sum }' "$1.node" "$1.ele"
}

gain_total=0
# one NAME INPUT SWITCHES VERIFY_ARGS
one() {
  name=$1 input=$2 sw=$3 vargs=$4
  ext=${input##*.}
  for run in plain t1 t2; do
    mkdir -p "$work/$name/$run"
    cp "$input" "$work/$name/$run/in.$ext"
  done
  "$deltri" -Q "$sw" "$work/$name/plain/in.$ext" 2>/dev/null || { fail "$name: $sw failed"; return; }
  for t in 1 2; do
    "$deltri" -Q "$sw" -C --smooth --threads=$t "$work/$name/t$t/in.$ext" 2>/dev/null ||
      { fail "$name: $sw -C --smooth --threads=$t failed"; return; }
  done
  for f in in.1.node in.1.ele; do
    cmp -s "$work/$name/t1/$f" "$work/$name/t2/$f" || fail "$name: $f differs between --threads=1 and --threads=2"
  done
  (cd "$work/$name/t1" && "$verify" --input "in.$ext" --mesh in.1 --refined $vargs) || fail "$name: deltri_mesh_verify found faults"
  set -- $(figures "$work/$name/plain/in.1") $(figures "$work/$name/t1/in.1")
  echo "$name $sw: $1 triangles; smallest angle $2 -> $5; mean smallest angle $(awk "BEGIN { printf \"%.3f -> %.3f\", $3 / $1, $6 / $4 }")"
  [ "$1" = "$4" ] || fail "$name: $1 triangles without --smooth, $4 with"
  awk "BEGIN { exit !($5 >= $2) }" || fail "$name: the smallest angle fell from $2 to $5"
  awk "BEGIN { exit !($6 >= $3 - 1e-6) }" || fail "$name: the mean smallest angle fell"
  gain_total=$(awk "BEGIN { printf \"%.12f\", $gain_total + $6 / $4 - $3 / $1 }")
}

one guitar "$data/guitar.poly" -pq30 "--min-angle 30"
one plate_a "$inputs/plate.poly" -pq28a0.002 "--min-angle 28 --max-area 0.002"
for seed in 1 2 3 4 5; do
  polygon $seed $((6 + seed)) >"$work/poly$seed.poly"
  one "polygon$seed" "$work/poly$seed.poly" -pq30a0.01 "--min-angle 30 --max-area 0.01"
done
polygon 9 40 >"$work/poly40.poly"
one polygon40 "$work/poly40.poly" -pq33 "--min-angle 33"
awk "BEGIN { exit !($gain_total > 1) }" || fail "the mean smallest angle rose by only $gain_total degrees in all"
[ $failed = 0 ] && echo "smooth: every mesh sound, bounds met, smallest angles kept, means raised (total $gain_total degrees)"
exit $failed
