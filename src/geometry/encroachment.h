// Whether a point encroaches upon a segment: lies in the segment's diametral circle or, for the
// lens variant (Shewchuk 2001, section 6.4), in its diametral lens.
#pragma once

#include "geometry/point.h"

namespace deltri {

// True iff p lies strictly inside the circle with diameter ab, i.e. (a - p) . (b - p) < 0, decided
// exactly (floating-point filter, then expansion arithmetic). Points on the circle, and a or b
// themselves, do not encroach. Exact under the same coordinate range as orient2d (predicates.h).
bool in_diametral_circle(const Point& a, const Point& b, const Point& p);

// True iff p, on either side of ab, sees ab at an angle strictly greater than
// 180 - 2 * min_angle_degrees: the interior of the lens bounded by two circular arcs through a and b
// that meet the segment at 2 * min_angle. For min_angle 30 each arc's centre lies on the other arc.
//
// Edge cases: min_angle <= 0 never encroaches (no angle exceeds 180); min_angle == 45 is exactly
// in_diametral_circle; min_angle above 45 gives a region larger than the diametral circle, and
// values above 90 are treated as 90 (everything except a, b and the line outside the segment).
// p equal to a or b never encroaches; points of the open segment ab do (for min_angle not
// within rounding of 0).
//
// Exactness: the obtuse-angle part of the test is exact (in_diametral_circle); the comparison with
// cos(2 min_angle) is floating point, so points within a few ulps (relative) of the lens arcs may be
// classified either way. At min_angle 45 no floating-point comparison is made.
bool in_diametral_lens(const Point& a, const Point& b, const Point& p, double min_angle_degrees);

}  // namespace deltri
