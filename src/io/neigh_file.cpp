#include "io/neigh_file.h"

#include "io/output_numbering.h"

namespace deltri {

void write_neigh_file(ByteSink& sink, const Mesh& mesh, int first_index) {
  const std::vector<std::uint32_t> numbers = number_live_triangles(mesh);
  sink.expect(static_cast<std::size_t>(mesh.live_triangles()) * 36);
  TextWriter out(sink);
  out.integer(mesh.live_triangles());
  out.next_integer(3);
  out.end_line();
  long long index = first_index;
  for (TriangleId t{0}; t < mesh.triangle_slots(); ++t) {
    if (!mesh.is_live(t)) continue;
    out.integer(index++);
    for (unsigned k = 0; k < 3; ++k) {
      const EdgeRef across = mesh.link[edge_of(t, (k + 1) % 3)];
      out.next_integer(across == kNone ? -1 : static_cast<long long>(triangle_number(numbers, triangle_of(across))) + first_index);
    }
    out.end_line();
  }
  out.finish();
}

void write_neigh_file(std::string& out, const Mesh& mesh, int first_index) {
  StringSink sink(out);
  write_neigh_file(sink, mesh, first_index);
}

}  // namespace deltri
