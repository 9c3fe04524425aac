// Where to split a bad triangle (Fig. 38 l.13): its circumcentre, or Ungor's off-centre when that
// is nearer the shortest edge. The off-centre lies on the shortest edge's bisector at the height
// where the new triangle on that edge has angle theta at the new vertex, (l/2) cot(theta/2); the
// reference scales it by 0.95 (0.475 cot(theta/2) l) so the new triangle is a little better than
// the bound. Off-centres give fewer triangles for the same bound.
#pragma once

#include "geometry/point.h"
#include "mesh/mesh.h"

namespace deltri {

// Circumcentre of a, b, c, computed relative to a for accuracy. The triangle must not be flat.
Point circumcenter_of(const Point& a, const Point& b, const Point& c);

// 0.475 cot(theta / 2), or 0 when off-centres are not wanted (then circumcentres are used).
double off_center_constant(double min_angle_deg, bool off_centers);

// The Steiner point for triangle_of(shortest), `shortest` being its shortest edge.
Point steiner_point(const Mesh& mesh, EdgeRef shortest, double off_constant);

}  // namespace deltri
