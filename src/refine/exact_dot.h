// The sign of (x - w) . (y - w), exactly: the diametral-circle test (Appendix A: w encroaches on
// xy when the angle at w is at least 90 degrees, i.e. this dot product is <= 0) must not flip for
// a vertex lying on the circle, or a conforming Delaunay mesh could keep an encroached subsegment.
#pragma once

#include "geometry/point.h"

namespace deltri {

// -1, 0 or +1.
int dot_sign(const Point& x, const Point& y, const Point& w);

}  // namespace deltri
