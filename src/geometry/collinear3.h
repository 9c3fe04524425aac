// Exact collinearity of points in space, from the 2-D predicates: three points lie on one line
// exactly when they do in each of the three coordinate planes. Exact for any finite doubles (no
// products of coordinates that can underflow, as a cross product's length does near 1e-150).
#pragma once

#include "geometry/point3.h"
#include "geometry/predicates.h"

namespace deltri {

inline bool collinear3(Predicates& pred, const Point3& o, const Point3& a, const Point3& b) {
  return pred.orient2d({o.x, o.y}, {a.x, a.y}, {b.x, b.y}) == 0.0 &&
         pred.orient2d({o.y, o.z}, {a.y, a.z}, {b.y, b.z}) == 0.0 &&
         pred.orient2d({o.x, o.z}, {a.x, a.z}, {b.x, b.z}) == 0.0;
}

}  // namespace deltri
