#include "cdt/markers.h"

namespace deltri {

void assign_boundary_markers(Mesh& mesh, bool input_had_markers) {
  const std::size_t n = mesh.vertex_count();
  if (!input_had_markers) mesh.marker.clear();
  mesh.marker.resize(n, 0);
  for (const Subsegment& s : mesh.subsegments) {
    if (s.a == kNone || s.marker == 0) continue;
    for (const VertexId v : {s.a, s.b})
      if (mesh.marker[v] == 0) mesh.marker[v] = s.marker;
  }
  // Links first: nearly every edge has a twin, so the corners are read only at the boundary and at
  // dead slots, half the memory traffic of this pass over every edge.
  for (EdgeRef e{0}; e < mesh.corner.size(); ++e) {
    if (mesh.link[e] != kNone || mesh.corner[e] == kNone) continue;
    for (const VertexId v : {mesh.org(e), mesh.dest(e)})
      if (mesh.marker[v] == 0) mesh.marker[v] = 1;
  }
}

}  // namespace deltri
