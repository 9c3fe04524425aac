#include "io/voronoi_file.h"

#include "geometry/constructions.h"
#include "io/edge_file.h"
#include "io/output_numbering.h"

namespace deltri {

Point voronoi_vertex(const Mesh& mesh, TriangleId t, std::vector<double>& attributes) {
  const std::size_t na = static_cast<std::size_t>(mesh.num_attributes);
  const auto [a, b, c] = mesh.corners(t);
  const Point &pa = mesh.points[a], &pb = mesh.points[b], &pc = mesh.points[c];
  const Point cc = circumcenter(pa, pb, pc);
  attributes.resize(na);
  if (na > 0) {
    // Barycentric coordinates of the circumcentre (outside the triangle when it is obtuse, so
    // the attributes are extrapolated along the same plane).
    const double area = triangle_area(pa, pb, pc);
    const double wb = triangle_area(pa, cc, pc) / area, wc = triangle_area(pa, pb, cc) / area;
    const double wa = 1.0 - wb - wc;
    for (std::size_t k = 0; k < na; ++k)
      attributes[k] = wa * mesh.attributes[a * na + k] + wb * mesh.attributes[b * na + k] + wc * mesh.attributes[c * na + k];
  }
  return cc;
}

void write_voronoi_node_file(ByteSink& sink, const Mesh& mesh, int first_index) {
  const std::size_t na = static_cast<std::size_t>(mesh.num_attributes);
  sink.expect(static_cast<std::size_t>(mesh.live_triangles()) * (48 + 24 * na));
  TextWriter out(sink);
  out.integer(mesh.live_triangles());
  out.next_integer(2);
  out.next_integer(static_cast<long long>(na));
  out.next_integer(0);
  out.end_line();
  std::vector<double> attributes;
  long long index = first_index;
  for (TriangleId t{0}; t < mesh.triangle_slots(); ++t) {
    if (!mesh.is_live(t)) continue;
    const Point cc = voronoi_vertex(mesh, t, attributes);
    out.integer(index++);
    out.next_real(cc.x);
    out.next_real(cc.y);
    for (std::size_t k = 0; k < na; ++k) out.next_real(attributes[k]);
    out.end_line();
  }
  out.finish();
}

void write_voronoi_edge_file(ByteSink& sink, const Mesh& mesh, int first_index) {
  const std::vector<std::uint32_t> numbers = number_live_triangles(mesh);
  const std::uint32_t count = count_edges(mesh);
  sink.expect(static_cast<std::size_t>(count) * 24);
  TextWriter out(sink);
  out.integer(count);
  out.next_integer(0);
  out.end_line();
  long long index = first_index;
  for (TriangleId t{0}; t < mesh.triangle_slots(); ++t) {
    if (!mesh.is_live(t)) continue;
    const long long here = static_cast<long long>(triangle_number(numbers, t)) + first_index;
    for (EdgeRef e : edges_of(t)) {
      if (!edge_written_here(mesh, e)) continue;
      out.integer(index++);
      out.next_integer(here);
      if (mesh.link[e] != kNone) {
        out.next_integer(static_cast<long long>(triangle_number(numbers, triangle_of(mesh.link[e]))) + first_index);
      } else {
        // The triangle lies to the left of org -> dest, so the right-hand normal points out.
        const Point &p = mesh.points[mesh.org(e)], &q = mesh.points[mesh.dest(e)];
        out.next_integer(-1);
        out.next_real(q.y - p.y);
        out.next_real(p.x - q.x);
      }
      out.end_line();
    }
  }
  out.finish();
}

}  // namespace deltri
