# Sourced by the e2e scripts.
#
# `run_in_scratch DELTRI INPUT SWITCHES` copies INPUT into a scratch directory (removed on exit),
# changes to it and runs deltri there, its stdout in `out` and stderr in `err`; the test fails if
# deltri exits non-zero. Sets `file` to INPUT's name.
run_in_scratch() {
  work=$(mktemp -d) || exit 1
  trap 'rm -rf "$work"' EXIT
  file=$(basename "$2")
  cp "$2" "$work/$file"
  cd "$work" || exit 1
  "$1" "$3" "$file" >out 2>err || { echo "FAIL: deltri $3 $file exited $?"; cat err; exit 1; }
}

# `measure BASE` prints the smallest angle (degrees) and the largest
# area of the triangles in BASE.node and BASE.ele, computed here in awk, independently of
# deltri's own statistics.
measure() {
  awk 'FNR == 1 { file++ } /^[ \t]*#/ || NF == 0 { next }
       file == 1 && !nh { nh = 1; next } file == 1 { x[$1] = $2; y[$1] = $3; next }
       file == 2 && !eh { eh = 1; next }
       file == 2 { a = $2; b = $3; c = $4
         area = ((x[b]-x[a])*(y[c]-y[a]) - (y[b]-y[a])*(x[c]-x[a])) / 2; if (area > amax) amax = area
         for (k = 0; k < 3; k++) {
           p = (k == 0 ? a : k == 1 ? b : c); q = (k == 0 ? b : k == 1 ? c : a); r = (k == 0 ? c : k == 1 ? a : b)
           ux = x[q]-x[p]; uy = y[q]-y[p]; vx = x[r]-x[p]; vy = y[r]-y[p]
           ang = atan2(ux*vy - uy*vx, ux*vx + uy*vy) * 45 / atan2(1, 1); if (amin == "" || ang < amin) amin = ang } }
       END { printf "%.9f %.17g\n", amin, amax }' "$1.node" "$1.ele"
}

