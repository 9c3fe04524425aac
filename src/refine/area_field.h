// Area bounds that vary from triangle to triangle of the mesh refinement starts from (-r with an
// .area file), kept as a field over the plane.
//
// Children inherit their parent's bound, which is exact for splits, but a flip, a cavity or a
// deleted vertex's star re-cuts several triangles at once, and a bound handed on by slot is then
// lost or moved (a sparse .area file once bounded one triangle, and a segment split that replaced it
// left two triangles of 0.25 and 0.5 in the bounded zone). The rule instead: a triangle's bound is
// that of the initial triangle its centroid lies in, found in a grid of the initial triangles.
// Region bounds need none of this (no cavity crosses a subsegment, so a region's triangles all
// carry its bound), and neither do uniform ones: the field is empty then, and nothing changes.
#pragma once

#include <cstdint>
#include <vector>

#include "geometry/point.h"
#include "geometry/triangle_grid.h"
#include "mesh/mesh.h"

namespace deltri {

class AreaField {
 public:
  // Empty unless two neighbouring triangles without a subsegment between them differ in bound.
  static AreaField of(const Mesh& mesh);
  bool empty() const { return triangles_.empty(); }
  // The bound (<= 0: none) of the initial triangle containing p; where p lies on sides shared by
  // several (to rounding), the tightest of theirs; outside all of them, the tightest in p's cell.
  double bound_at(const Point& p) const;

 private:
  struct Triangle {
    Point a, b, c;
    double bound;
  };
  std::vector<Triangle> triangles_;
  TriangleGrid grid_;
};

}  // namespace deltri
