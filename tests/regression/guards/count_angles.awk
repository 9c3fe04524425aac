# count_angles.awk -v q=BOUND -v eps=TOL NODE ELE: prints how many triangles have their smallest
# angle below q-eps and below q+eps (angles from the coordinates, by the law of cosines via atan2).
FNR == 1 { file++; next }
/^#/ { next }
file == 1 { x[$1] = $2; y[$1] = $3; next }
file == 2 {
  ax = x[$2]; ay = y[$2]; bx = x[$3]; by = y[$3]; cx = x[$4]; cy = y[$4]
  m = 180
  m = min3(ang(ax, ay, bx, by, cx, cy), ang(bx, by, cx, cy, ax, ay), ang(cx, cy, ax, ay, bx, by))
  if (m < q - eps) lo++
  if (m < q + eps) hi++
}
function ang(px, py, ux, uy, wx, wy,   a, b, c, d) {
  a = ux - px; b = uy - py; c = wx - px; d = wy - py
  return atan2((a * d - b * c) < 0 ? -(a * d - b * c) : (a * d - b * c), a * c + b * d) * 57.29577951308232
}
function min3(a, b, c) { return a < b ? (a < c ? a : c) : (b < c ? b : c) }
END { printf "%d %d\n", lo, hi }
