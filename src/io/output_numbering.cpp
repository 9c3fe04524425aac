#include "io/output_numbering.h"

namespace deltri {

std::vector<std::uint32_t> number_live_triangles(const Mesh& mesh) {
  std::vector<std::uint32_t> numbers;
  if (mesh.free_triangles.empty()) return numbers;
  numbers.assign(mesh.triangle_slots(), kNone);
  std::uint32_t next = 0;
  for (TriangleId t{0}; t < mesh.triangle_slots(); ++t)
    if (mesh.is_live(t)) numbers[t] = next++;
  return numbers;
}

std::vector<EdgeRef> boundary_and_segment_edges(const Mesh& mesh) {
  std::vector<EdgeRef> edges;
  for (TriangleId t{0}; t < mesh.triangle_slots(); ++t) {
    if (!mesh.is_live(t)) continue;
    for (EdgeRef e : edges_of(t))
      if (edge_written_here(mesh, e) && (mesh.link[e] == kNone || (mesh.has_subsegments() && mesh.subseg.has(e))))
        edges.push_back(e);
  }
  return edges;
}

int edge_marker(const Mesh& mesh, EdgeRef e) {
  if (mesh.has_subsegments() && mesh.subseg.has(e)) {
    const int marker = mesh.subsegments[mesh.subseg[e]].marker;
    if (marker != 0) return marker;
  }
  return mesh.link[e] == kNone ? 1 : 0;
}

void write_points_xyz(TextWriter& out, const Mesh& mesh, const VertexNumbering& number) {
  for (VertexId v{0}; v < mesh.vertex_count(); ++v)
    if (number.written(v)) {
      TextWriter::Line line = out.line(3);
      line.real(mesh.points[v].x);
      line.next_real(mesh.points[v].y);
      line.next_integer(0);
      line.end_line();
    }
}

}  // namespace deltri
