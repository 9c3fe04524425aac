// Where to split an encroached subsegment (Fig. 39 l.39; Sec. 6.2, Fig. 25): if an endpoint is an
// acute apex (clusters.h: two subsegments at less than 90 degrees), on the circle around it whose radius is the power of two that falls in
// [|s|/3, 2|s|/3); otherwise at the midpoint. Subsegments at an apex then have power-of-two
// lengths, equal ones do not encroach on each other, and the runaway cycle of Fig. 24 cannot start.
#pragma once

#include "geometry/point.h"

namespace deltri {

// The power of two in [length/3, 2 length/3).
double shell_radius(double length);

// The split point of subsegment ab; at most one of the endpoints is used as the shells' centre
// (a when both qualify, Sec. 6.2: "choose one endpoint's shells arbitrarily").
Point shell_split_point(const Point& a, const Point& b, bool a_is_apex, bool b_is_apex);

}  // namespace deltri
