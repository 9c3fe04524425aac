#include "surface/surface_files.h"

namespace deltri {

void write_surface_node(ByteSink& sink, const SurfaceMesh& mesh, const SurfaceWriteOptions& options) {
  TextWriter out(sink);
  const bool markers = options.markers && mesh.has_markers;
  out.integer(static_cast<long long>(mesh.points.size()));
  out.text(" 3 0");
  out.next_integer(markers ? 1 : 0);
  out.end_line();
  for (std::size_t v = 0; v < mesh.points.size(); ++v) {
    TextWriter::Line line = out.line(5);
    line.integer(static_cast<long long>(v) + options.first_index);
    line.next_real(mesh.points[v].x);
    line.next_real(mesh.points[v].y);
    line.next_real(mesh.points[v].z);
    if (markers) line.next_integer(mesh.markers[v]);
    line.end_line();
  }
  out.finish();
}

void write_surface_ele(ByteSink& sink, const SurfaceMesh& mesh, const SurfaceWriteOptions& options) {
  TextWriter out(sink);
  out.integer(static_cast<long long>(mesh.triangle_count()));
  out.text(" 3 1");
  out.end_line();
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    TextWriter::Line line = out.line(5);
    line.integer(static_cast<long long>(t) + options.first_index);
    for (const std::uint32_t v : mesh.triangles[t]) line.next_integer(static_cast<long long>(v) + options.first_index);
    line.next_integer(mesh.facet_marker[mesh.triangle_facet[t]]);
    line.end_line();
  }
  out.finish();
}

void write_surface_edge(ByteSink& sink, const SurfaceMesh& mesh, const SurfaceWriteOptions& options) {
  TextWriter out(sink);
  out.integer(static_cast<long long>(mesh.subsegments.size()));
  out.next_integer(options.markers ? 1 : 0);
  out.end_line();
  for (std::size_t s = 0; s < mesh.subsegments.size(); ++s) {
    const SurfaceMesh::Edge& e = mesh.subsegments[s];
    TextWriter::Line line = out.line(4);
    line.integer(static_cast<long long>(s) + options.first_index);
    line.next_integer(static_cast<long long>(e.a) + options.first_index);
    line.next_integer(static_cast<long long>(e.b) + options.first_index);
    if (options.markers) line.next_integer(mesh.subsegment_marker(s));
    line.end_line();
  }
  out.finish();
}

}  // namespace deltri
