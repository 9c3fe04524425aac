#include "mesh/ghosts.h"

#include "mesh/internal.h"

namespace deltri {

void seed_with_ghosts(Mesh& mesh, VertexId a, VertexId b, VertexId c) {
  const TriangleId t = mesh.add_triangle(a, b, c);
  TriangleId ghost[3];
  for (unsigned i = 0; i < 3; ++i) {
    const EdgeRef e = edge_of(t, i);
    ghost[i] = mesh.add_triangle(mesh.dest(e), mesh.org(e), kGhostVertex);
    mesh.bond(e, edge_of(ghost[i], 0));
  }
  // Ghost i ends (side 2, ghost -> corner i+1) where ghost i+1 begins (side 1, corner i+1 ->
  // ghost).
  for (unsigned i = 0; i < 3; ++i) mesh.bond(edge_of(ghost[i], 2), edge_of(ghost[(i + 1) % 3], 1));
}

void remove_ghosts(Mesh& mesh) {
  for (TriangleId t{0}; t < mesh.triangle_slots(); ++t)
    if (mesh.is_live(t) && detail::is_ghost(mesh, t)) mesh.kill_triangle(t);
  mesh.compact_triangles();
}

}  // namespace deltri
