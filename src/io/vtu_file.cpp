#include "io/vtu_file.h"

#include <bit>
#include <cstdint>
#include <functional>
#include <string>

#include "io/binary_writer.h"

namespace deltri {
namespace {

void open_array(TextWriter& out, const char* type, const std::string& name, int components = 1) {
  out.text(std::string("<DataArray type=\"") + type + "\"");
  if (!name.empty()) out.text(" Name=\"" + name + "\"");
  if (components > 1) out.text(" NumberOfComponents=\"" + std::to_string(components) + "\"");
  out.text(" format=\"ascii\">\n");
}

// A DataArray of the binary variant: its XML element and the code that writes its raw values.
struct RawArray {
  const char* type;
  std::string name;
  int components;
  std::size_t values;      // number of values (components included)
  std::size_t value_bytes;
  std::function<void(BinaryWriter&)> write;
};

// The binary variant: the same arrays as the ASCII one, as raw appended data (each array a UInt64
// byte count, then its values), which ParaView, VTK and meshio read.
void write_binary_vtu(ByteSink& sink, const Mesh& mesh, const ExportOptions& options) {
  const VertexNumbering number{options.numbering, 0};
  const std::vector<VertexId>* mid = options.midpoints;
  const std::uint32_t point_count = number.written_count(mesh.vertex_count());
  const std::vector<EdgeRef> lines = options.markers ? boundary_and_segment_edges(mesh) : std::vector<EdgeRef>{};
  std::vector<TriangleId> triangles;
  for (TriangleId t{0}; t < mesh.triangle_slots(); ++t)
    if (mesh.is_live(t)) triangles.push_back(t);
  const std::size_t cells = lines.size() + triangles.size();
  const int nva = mesh.num_attributes, nta = mesh.num_triangle_attributes;
  const auto each_point = [&](BinaryWriter& w, const std::function<void(BinaryWriter&, VertexId)>& f) {
    for (VertexId v{0}; v < mesh.vertex_count(); ++v)
      if (number.written(v)) f(w, v);
  };
  std::vector<RawArray> point_data, cell_data, geometry;
  if (options.markers && !mesh.marker.empty())
    point_data.push_back({"Int32", "marker", 1, point_count, 4, [&](BinaryWriter& w) {
                            each_point(w, [&](BinaryWriter& o, VertexId v) { o.put(static_cast<std::int32_t>(mesh.marker[v])); });
                          }});
  for (int k = 0; k < nva; ++k)
    point_data.push_back({"Float64", "attribute_" + std::to_string(k + 1), 1, point_count, 8, [&, k](BinaryWriter& w) {
                            each_point(w, [&](BinaryWriter& o, VertexId v) { o.put(mesh.attributes[static_cast<std::size_t>(v) * nva + k]); });
                          }});
  if (options.markers)
    cell_data.push_back({"Int32", "marker", 1, cells, 4, [&](BinaryWriter& w) {
                           for (EdgeRef e : lines) w.put(static_cast<std::int32_t>(edge_marker(mesh, e)));
                           for (std::size_t k = 0; k < triangles.size(); ++k) w.put(std::int32_t{0});
                         }});
  for (int k = 0; k < nta; ++k)
    cell_data.push_back({"Float64", "attribute_" + std::to_string(k + 1), 1, cells, 8, [&, k](BinaryWriter& w) {
                           for (std::size_t j = 0; j < lines.size(); ++j) w.put(0.0);
                           for (TriangleId t : triangles) w.put(mesh.triangle_attributes[static_cast<std::size_t>(t) * nta + k]);
                         }});
  constexpr std::size_t kXyz = 3;  // VTK points have three coordinates
  geometry.push_back({"Float64", "", 3, kXyz * point_count, 8, [&](BinaryWriter& w) {
                        each_point(w, [&](BinaryWriter& o, VertexId v) {
                          o.put(mesh.points[v].x), o.put(mesh.points[v].y), o.put(0.0);
                        });
                      }});
  const std::size_t per_line = mid ? 3 : 2, per_triangle = mid ? 6 : 3;
  geometry.push_back({"Int64", "connectivity", 1, lines.size() * per_line + triangles.size() * per_triangle, 8, [&](BinaryWriter& w) {
                        const auto put = [&](VertexId v) { w.put(static_cast<std::int64_t>(number(v))); };
                        for (EdgeRef e : lines) {
                          put(mesh.org(e)), put(mesh.dest(e));
                          if (mid) put((*mid)[lprev(e)]);
                        }
                        for (TriangleId t : triangles) {
                          for (unsigned c = 0; c < 3; ++c) put(mesh.corner[edge_of(t, c)]);
                          if (mid)
                            for (unsigned c : {2u, 0u, 1u}) put((*mid)[edge_of(t, c)]);
                        }
                      }});
  geometry.push_back({"Int64", "offsets", 1, cells, 8, [&](BinaryWriter& w) {
                        std::int64_t offset = 0;
                        for (std::size_t k = 0; k < cells; ++k) w.put(offset += static_cast<std::int64_t>(k < lines.size() ? per_line : per_triangle));
                      }});
  geometry.push_back({"UInt8", "types", 1, cells, 1, [&](BinaryWriter& w) {
                        for (std::size_t k = 0; k < cells; ++k) w.put(static_cast<std::uint8_t>(k < lines.size() ? (mid ? 21 : 3) : (mid ? 22 : 5)));
                      }});

  std::string xml = std::string("<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"") +
                    (std::endian::native == std::endian::little ? "LittleEndian" : "BigEndian") +
                    "\" header_type=\"UInt64\">\n<UnstructuredGrid>\n<Piece NumberOfPoints=\"" + std::to_string(point_count) +
                    "\" NumberOfCells=\"" + std::to_string(cells) + "\">\n";
  std::size_t offset = 0;
  const auto declare = [&](const std::vector<RawArray>& arrays, const char* open, const char* close) {
    xml += open;
    for (const RawArray& a : arrays) {
      xml += std::string("<DataArray type=\"") + a.type + "\"";
      if (!a.name.empty()) xml += " Name=\"" + a.name + "\"";
      if (a.components > 1) xml += " NumberOfComponents=\"" + std::to_string(a.components) + "\"";
      xml += " format=\"appended\" offset=\"" + std::to_string(offset) + "\"/>\n";
      offset += sizeof(std::uint64_t) + a.values * a.value_bytes;
    }
    xml += close;
  };
  declare(point_data, "<PointData>\n", "</PointData>\n");
  declare(cell_data, "<CellData>\n", "</CellData>\n");
  declare({geometry[0]}, "<Points>\n", "</Points>\n");
  declare({geometry.begin() + 1, geometry.end()}, "<Cells>\n", "</Cells>\n");
  xml += "</Piece>\n</UnstructuredGrid>\n<AppendedData encoding=\"raw\">\n_";
  sink.expect(xml.size() + offset + 40);
  BinaryWriter out(sink);
  out.text(xml);
  for (const std::vector<RawArray>* arrays : {&point_data, &cell_data, &geometry})
    for (const RawArray& a : *arrays) {
      out.put(static_cast<std::uint64_t>(a.values * a.value_bytes));
      a.write(out);
    }
  out.text("\n</AppendedData>\n</VTKFile>\n");
  out.finish();
}

}  // namespace

void write_vtu_file(ByteSink& sink, const Mesh& mesh, const ExportOptions& options, bool binary) {
  if (binary) return write_binary_vtu(sink, mesh, options);
  const VertexNumbering number{options.numbering, 0};
  const std::vector<VertexId>* mid = options.midpoints;
  const std::uint32_t point_count = number.written_count(mesh.vertex_count());
  const std::vector<EdgeRef> lines = options.markers ? boundary_and_segment_edges(mesh) : std::vector<EdgeRef>{};
  std::vector<TriangleId> triangles;
  for (TriangleId t{0}; t < mesh.triangle_slots(); ++t)
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
    for (VertexId v{0}; v < mesh.vertex_count(); ++v)
      if (number.written(v)) {
        out.integer(mesh.marker[v]);
        out.end_line();
      }
    out.text("</DataArray>\n");
  }
  for (int k = 0; k < nva; ++k) {
    open_array(out, "Float64", "attribute_" + std::to_string(k + 1));
    for (VertexId v{0}; v < mesh.vertex_count(); ++v)
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
    const auto [a, b, c] = mesh.corners(t);
    line.integer(number(a));
    line.next_integer(number(b));
    line.next_integer(number(c));
    // VTK orders the midpoints by edge: (0,1), (1,2), (2,0), i.e. opposite corners 2, 0, 1.
    if (mid)
      for (unsigned c : {2u, 0u, 1u}) line.next_integer(number((*mid)[edge_of(t, c)]));
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
