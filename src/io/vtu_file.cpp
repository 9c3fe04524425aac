#include "io/vtu_file.h"

#include <string>

namespace deltri {
namespace {

void open_array(TextWriter& out, const char* type, const std::string& name, int components = 1) {
  out.text(std::string("<DataArray type=\"") + type + "\"");
  if (!name.empty()) out.text(" Name=\"" + name + "\"");
  if (components > 1) out.text(" NumberOfComponents=\"" + std::to_string(components) + "\"");
  out.text(" format=\"ascii\">\n");
}

}  // namespace

void write_vtu_file(ByteSink& sink, const Mesh& mesh, const ExportOptions& options) {
  const VertexNumbering number{options.numbering, 0};
  const std::vector<VertexId>* mid = options.midpoints;
  const std::uint32_t point_count = number.written_count(mesh.vertex_count());
  const std::vector<EdgeRef> lines = options.markers ? boundary_and_segment_edges(mesh) : std::vector<EdgeRef>{};
  std::vector<TriangleId> triangles;
  for (TriangleId t = 0; t < mesh.triangle_slots(); ++t)
    if (mesh.is_live(t)) triangles.push_back(t);
  const std::size_t cells = lines.size() + triangles.size();
  const int nva = mesh.num_attributes, nta = mesh.num_triangle_attributes;
  sink.expect(static_cast<std::size_t>(point_count) * 48 + triangles.size() * (mid ? 64 : 40));

  TextWriter out(sink);
  out.text("<?xml version=\"1.0\"?>\n"
           "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
           "<UnstructuredGrid>\n<Piece NumberOfPoints=\"" + std::to_string(point_count) +
           "\" NumberOfCells=\"" + std::to_string(cells) + "\">\n<PointData>\n");
  if (options.markers && !mesh.marker.empty()) {
    open_array(out, "Int32", "marker");
    for (VertexId v = 0; v < mesh.vertex_count(); ++v)
      if (number.written(v)) {
        out.integer(mesh.marker[v]);
        out.end_line();
      }
    out.text("</DataArray>\n");
  }
  for (int k = 0; k < nva; ++k) {
    open_array(out, "Float64", "attribute_" + std::to_string(k + 1));
    for (VertexId v = 0; v < mesh.vertex_count(); ++v)
      if (number.written(v)) {
        out.real(mesh.attributes[static_cast<std::size_t>(v) * nva + k]);
        out.end_line();
      }
    out.text("</DataArray>\n");
  }
  out.text("</PointData>\n<CellData>\n");
  if (options.markers) {
    open_array(out, "Int32", "marker");
    for (EdgeRef e : lines) {
      out.integer(edge_marker(mesh, e));
      out.end_line();
    }
    for (std::size_t k = 0; k < triangles.size(); ++k) out.text("0\n");
    out.text("</DataArray>\n");
  }
  for (int k = 0; k < nta; ++k) {
    open_array(out, "Float64", "attribute_" + std::to_string(k + 1));
    for (std::size_t j = 0; j < lines.size(); ++j) out.text("0\n");
    for (TriangleId t : triangles) {
      out.real(mesh.triangle_attributes[static_cast<std::size_t>(t) * nta + k]);
      out.end_line();
    }
    out.text("</DataArray>\n");
  }
  out.text("</CellData>\n<Points>\n");
  open_array(out, "Float64", "", 3);
  write_points_xyz(out, mesh, number);
  out.text("</DataArray>\n</Points>\n<Cells>\n");
  open_array(out, "Int64", "connectivity");
  for (EdgeRef e : lines) {
    TextWriter::Line line = out.line(3);
    line.integer(number(mesh.org(e)));
    line.next_integer(number(mesh.dest(e)));
    if (mid) line.next_integer(number((*mid)[lprev(e)]));
    line.end_line();
  }
  for (TriangleId t : triangles) {
    TextWriter::Line line = out.line(6);
    line.integer(number(mesh.corner[3 * t]));
    line.next_integer(number(mesh.corner[3 * t + 1]));
    line.next_integer(number(mesh.corner[3 * t + 2]));
    // VTK orders the midpoints by edge: (0,1), (1,2), (2,0), i.e. opposite corners 2, 0, 1.
    if (mid)
      for (EdgeRef c : {2u, 0u, 1u}) line.next_integer(number((*mid)[3 * t + c]));
    line.end_line();
  }
  out.text("</DataArray>\n");
  open_array(out, "Int64", "offsets");
  long long offset = 0;
  for (std::size_t k = 0; k < cells; ++k) {
    offset += k < lines.size() ? (mid ? 3 : 2) : (mid ? 6 : 3);
    out.integer(offset);
    out.end_line();
  }
  out.text("</DataArray>\n");
  open_array(out, "UInt8", "types");
  for (std::size_t k = 0; k < cells; ++k) {
    out.integer(k < lines.size() ? (mid ? 21 : 3) : (mid ? 22 : 5));
    out.end_line();
  }
  out.text("</DataArray>\n</Cells>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n");
  out.finish();
}

}  // namespace deltri
