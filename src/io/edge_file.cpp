#include "io/edge_file.h"

#include "io/output_numbering.h"

namespace deltri {

std::uint32_t count_edges(const Mesh& mesh) {
  std::uint32_t count = 0;
  for (TriangleId t{0}; t < mesh.triangle_slots(); ++t)
    if (mesh.is_live(t))
      for (EdgeRef e : edges_of(t)) count += edge_written_here(mesh, e);
  return count;
}

void write_edge_file(ByteSink& sink, const Mesh& mesh, const EdgeWriteOptions& options) {
  const VertexNumbering number{options.numbering, options.first_index};
  const std::uint32_t count = count_edges(mesh);
  sink.expect(static_cast<std::size_t>(count) * 32);
  TextWriter out(sink);
  out.integer(count);
  out.next_integer(options.markers ? 1 : 0);
  out.end_line();
  long long index = options.first_index;
  for (TriangleId t{0}; t < mesh.triangle_slots(); ++t) {
    if (!mesh.is_live(t)) continue;
    for (EdgeRef e : edges_of(t)) {
      if (!edge_written_here(mesh, e)) continue;
      out.integer(index++);
      out.next_integer(number(mesh.org(e)));
      out.next_integer(number(mesh.dest(e)));
      if (options.markers) out.next_integer(edge_marker(mesh, e));
      out.end_line();
    }
  }
  out.finish();
}

void write_edge_file(std::string& out, const Mesh& mesh, const EdgeWriteOptions& options) {
  StringSink sink(out);
  write_edge_file(sink, mesh, options);
}

}  // namespace deltri
