#include "refine/steiner_point.h"

#include "geometry/constructions.h"

namespace deltri {

Point steiner_point(const Mesh& mesh, EdgeRef shortest, double off_center_factor) {
  return off_center(mesh.point(mesh.org(shortest)), mesh.point(mesh.dest(shortest)), mesh.point(mesh.apex(shortest)),
                    off_center_factor);
}

}  // namespace deltri
