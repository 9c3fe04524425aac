#include "refine/steiner_point.h"

#include "geometry/constructions.h"

namespace deltri {

Point steiner_point(const Mesh& mesh, EdgeRef shortest, double off_center_factor) {
  return off_center(mesh.point(mesh.org(shortest)), mesh.point(mesh.dest(shortest)), mesh.point(mesh.apex(shortest)),
                    off_center_factor);
}

Point steiner_point_of(const Point& a, const Point& b, const Point& c, double off_center_factor) {
  const double ab = squared_distance(a, b), bc = squared_distance(b, c), ca = squared_distance(c, a);
  if (ab <= bc && ab <= ca) return off_center(a, b, c, off_center_factor);
  if (bc <= ca) return off_center(b, c, a, off_center_factor);
  return off_center(c, a, b, off_center_factor);
}

}  // namespace deltri
