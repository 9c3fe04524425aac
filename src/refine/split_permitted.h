// SPLITPERMITTED (Fig. 38 l.27-35): may a subsegment encroached upon by a rejected Steiner point
// be split? Refused only when splitting would cut a whole subsegment cluster down to |s|/2 and
// thereby create a free edge shorter than d, the shortest edge of the bad triangle (Sec. 6.5's
// stand-in for r_g). This is what makes the Terminator terminate with small input angles.
#pragma once

#include "mesh/mesh.h"
#include "refine/clusters.h"

namespace deltri {

// Relative tolerance for "is a power of two" and "is shorter" (l.27, l.30): lengths come from
// rounded coordinates.
inline constexpr double kLengthTolerance = 1e-3;

bool is_power_of_two_length(double length);

// `s` is an edge carrying the subsegment; d the length of the bad triangle's shortest edge.
bool split_permitted(const Mesh& mesh, const SegmentApices& apices, EdgeRef s, double d);

}  // namespace deltri
