#include "mesh/remove_triangles.h"

namespace deltri {

void remove_triangles(Mesh& mesh, std::span<const TriangleId> dead) {
  for (const TriangleId t : dead) mesh.kill_triangle(t);
}

}  // namespace deltri
