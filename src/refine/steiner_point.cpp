#include "refine/steiner_point.h"

#include "geometry/constructions.h"
#include "refine/criteria.h"

namespace deltri {

Point steiner_point(const Mesh& mesh, EdgeRef shortest, double off_center_factor) {
  return off_center(mesh.point(mesh.org(shortest)), mesh.point(mesh.dest(shortest)), mesh.point(mesh.apex(shortest)),
                    off_center_factor);
}

Point steiner_point_of(const Point& a, const Point& b, const Point& c, double off_center_factor) {
  const Point* p[3] = {&a, &b, &c};
  const double len2[3] = {squared_distance(a, b), squared_distance(b, c), squared_distance(c, a)};
  const unsigned s = shortest_side(len2);
  return off_center(*p[s], *p[(s + 1) % 3], *p[(s + 2) % 3], off_center_factor);
}

}  // namespace deltri
