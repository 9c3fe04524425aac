// Where to split a bad triangle (Fig. 38 l.13): its circumcentre, or Ungor's off-centre when that
// is nearer the shortest edge (geometry/constructions.h, off_center). Off-centres give fewer
// triangles for the same bound.
#pragma once

#include "geometry/point.h"
#include "mesh/mesh.h"

namespace deltri {

// The Steiner point for triangle_of(shortest), `shortest` being its shortest edge; off_center_factor
// is AngleBound::off_center_factor(), or 0 for the circumcentre (-k).
Point steiner_point(const Mesh& mesh, EdgeRef shortest, double off_center_factor);

// The same for a triangle abc (counter-clockwise) that is not in the mesh yet: -Y's look-ahead.
Point steiner_point_of(const Point& a, const Point& b, const Point& c, double off_center_factor);

}  // namespace deltri
