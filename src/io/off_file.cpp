#include "io/off_file.h"

#include "io/edge_file.h"
#include "io/output_numbering.h"

namespace deltri {

void write_off_file(ByteSink& sink, const Mesh& mesh, const std::vector<std::uint32_t>* numbering) {
  const VertexNumbering number{numbering, 0};
  std::uint32_t vertices = 0;
  for (VertexId v{0}; v < mesh.vertex_count(); ++v) vertices += number.written(v);
  sink.expect(static_cast<std::size_t>(vertices) * 40 + static_cast<std::size_t>(mesh.live_triangles()) * 30);
  TextWriter out(sink);
  out.text("OFF\n");
  out.integer(vertices);
  out.next_integer(mesh.live_triangles());
  out.next_integer(count_edges(mesh));
  out.end_line();
  for (VertexId v{0}; v < mesh.vertex_count(); ++v) {
    if (!number.written(v)) continue;
    TextWriter::Line line = out.line(3);
    line.real(mesh.points[v].x);
    line.next_real(mesh.points[v].y);
    line.next_integer(0);
    line.end_line();
  }
  for (TriangleId t{0}; t < mesh.triangle_slots(); ++t) {
    if (!mesh.is_live(t)) continue;
    TextWriter::Line line = out.line(4);
    line.integer(3);
    for (EdgeRef e : edges_of(t)) line.next_integer(number(mesh.corner[e]));
    line.end_line();
  }
  out.finish();
}

}  // namespace deltri
