#!/bin/sh
# The random sweep's run 785 at seed 48 (tests/regression/inputs/sweep-lopping-pq34-hang.poly):
# two nearly vertical segments meet at about 1e-15 radians and a third crosses both within a few
# ulps, near (0.25, 0.854). At -pq34 the bottom-scale points (BottomScale::point) made new bad
# lattice triangles a little longer-edged than the one they were for, which made more: a front
# that crept out through good territory one lattice step at a time (12,000 Steiner points under
# -S12000, 1,800 ulps out, with --steiner=offcentre or --corner-lopping; at 2^300 with -j too).
# A new triangle under twice the bad triangle's scale must now be good, better than it, or no
# worse than the triangle it replaces (refine/bottom_scale.cpp, rate). Each run must end (CTest's
# timeout), exit 0 with its misses counted, and pass deltri_mesh_verify.
#   bottom-scale-front.sh DELTRI VERIFY
. "$(dirname "$0")/lib.sh"
input="$(dirname "$0")/../inputs/sweep-lopping-pq34-hang.poly"
case $input in /*) ;; *) input="$OLDPWD/$input" ;; esac
cp "$input" front.poly || fail "no input $input"
for switches in "-pq34 --steiner=offcentre" "-pq34 --corner-lopping" "-pq34"; do
  ends_counted front.poly front.1 $switches front.poly
done
# The sweep's own run: the same input times 2^300 (exact: a power of two), with -j.
awk 'NR == 4 { n = $1 } NR > 4 && NR <= 4 + n { printf "%s %.17g %.17g\n", $1, $2 * 2^300, $3 * 2^300; next } { print }' \
  front.poly >front300.poly
for switches in "-pq34j --steiner=offcentre" "-pq34j --corner-lopping"; do
  ends_counted front300.poly front300.1 $switches front300.poly
done
echo "ok"
