#include "io/midpoints.h"

#include "io/output_numbering.h"

namespace deltri {

std::vector<VertexId> add_edge_midpoints(Mesh& mesh) {
  std::vector<VertexId> midpoint(mesh.corner.size(), kNone);
  const std::size_t na = static_cast<std::size_t>(mesh.num_attributes);
  // Vertex markers exist in every output run (assign_boundary_markers fills them), but a mesh
  // built without them must not gain a half-filled array.
  const bool markers = !mesh.marker.empty();
  for (TriangleId t{0}; t < mesh.triangle_slots(); ++t) {
    if (!mesh.is_live(t)) continue;
    for (EdgeRef e : edges_of(t)) {
      // Edge e runs from corner e to corner lnext(e): it lies opposite corner lprev(e).
      const EdgeRef opposite = lprev(e);
      if (!edge_written_here(mesh, e)) {
        midpoint[opposite] = midpoint[lprev(mesh.link[e])];
        continue;
      }
      const VertexId a = mesh.org(e), b = mesh.dest(e);
      const Point pa = mesh.points[a], pb = mesh.points[b];
      const VertexId m = mesh.add_vertex({0.5 * (pa.x + pb.x), 0.5 * (pa.y + pb.y)},
                                         mesh.link[e] == kNone || (mesh.has_subsegments() && mesh.subseg.has(e))
                                             ? VertexKind::Segment
                                             : VertexKind::Free);
      for (std::size_t k = 0; k < na; ++k)
        mesh.attributes[m * na + k] = 0.5 * (mesh.attributes[a * na + k] + mesh.attributes[b * na + k]);
      if (markers) mesh.marker[m] = edge_marker(mesh, e);
      midpoint[opposite] = m;
    }
  }
  return midpoint;
}

}  // namespace deltri
