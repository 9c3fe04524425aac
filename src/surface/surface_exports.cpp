// The single-file formats of a surface mesh (declared in surface_files.h): OFF, STL, MSH 2.2, VTU.
#include "surface/surface_files.h"

#include "io/physical_groups.h"

namespace deltri {
namespace {

void write_xyz(TextWriter& out, const Point3& p) {
  TextWriter::Line line = out.line(3);
  line.real(p.x);
  line.next_real(p.y);
  line.next_real(p.z);
  line.end_line();
}

}  // namespace

void write_surface_off(ByteSink& sink, const SurfaceMesh& mesh) {
  TextWriter out(sink);
  out.text("OFF\n");
  out.integer(static_cast<long long>(mesh.points.size()));
  out.next_integer(static_cast<long long>(mesh.triangle_count()));
  out.next_integer(0);
  out.end_line();
  for (const Point3& p : mesh.points) write_xyz(out, p);
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    TextWriter::Line line = out.line(4);
    line.integer(3);
    for (const std::uint32_t v : mesh.triangles[t]) line.next_integer(v);
    line.end_line();
  }
  out.finish();
}

// Each triangle's normal is its facet's (the triangles of a facet are counter-clockwise about it).
void write_surface_stl(ByteSink& sink, const SurfaceMesh& mesh) {
  TextWriter out(sink);
  out.text("solid deltri\n");
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    const Point3& n = mesh.planes[mesh.triangle_facet[t]].normal;
    out.text("facet normal");
    out.next_real(n.x);
    out.next_real(n.y);
    out.next_real(n.z);
    out.text("\nouter loop\n");
    for (const std::uint32_t v : mesh.triangles[t]) {
      const Point3& p = mesh.points[v];
      out.text("vertex");
      out.next_real(p.x);
      out.next_real(p.y);
      out.next_real(p.z);
      out.end_line();
    }
    out.text("endloop\nendfacet\n");
  }
  out.text("endsolid deltri\n");
  out.finish();
}

// Triangles grouped by facet marker, tagged by the rule of io/physical_groups.h (a marker that is
// a positive integer is its own tag; 0 and negative markers, which Gmsh cannot take as tags, the
// next ones).
void write_surface_msh(ByteSink& sink, const SurfaceMesh& mesh) {
  std::vector<double> markers;
  markers.reserve(mesh.triangle_count());
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) markers.push_back(mesh.facet_marker[mesh.triangle_facet[t]]);
  const PhysicalGroups groups = marker_groups(markers);
  TextWriter out(sink);
  out.text("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n");
  out.integer(static_cast<long long>(groups.values.size()));
  out.end_line();
  for (std::size_t g = 0; g < groups.values.size(); ++g) {
    out.text("2 ");
    out.integer(groups.tags[g]);
    out.text(" \"marker " + value_text(groups.values[g]) + "\"\n");
  }
  out.text("$EndPhysicalNames\n$Nodes\n");
  out.integer(static_cast<long long>(mesh.points.size()));
  out.end_line();
  for (std::size_t v = 0; v < mesh.points.size(); ++v) {
    TextWriter::Line line = out.line(4);
    line.integer(static_cast<long long>(v) + 1);
    line.next_real(mesh.points[v].x);
    line.next_real(mesh.points[v].y);
    line.next_real(mesh.points[v].z);
    line.end_line();
  }
  out.text("$EndNodes\n$Elements\n");
  out.integer(static_cast<long long>(mesh.triangle_count()));
  out.end_line();
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    TextWriter::Line line = out.line(9);
    line.integer(static_cast<long long>(t) + 1);
    line.next_integer(2);  // a 3-node triangle
    line.next_integer(2);  // two tags
    line.next_integer(groups.tags[groups.group[t]]);
    line.next_integer(static_cast<long long>(mesh.triangle_facet[t]) + 1);
    for (const std::uint32_t v : mesh.triangles[t]) line.next_integer(static_cast<long long>(v) + 1);
    line.end_line();
  }
  out.text("$EndElements\n");
  out.finish();
}

void write_surface_vtu(ByteSink& sink, const SurfaceMesh& mesh) {
  TextWriter out(sink);
  const long long n = static_cast<long long>(mesh.triangle_count());
  out.text("<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
           "<UnstructuredGrid>\n<Piece NumberOfPoints=\"");
  out.integer(static_cast<long long>(mesh.points.size()));
  out.text("\" NumberOfCells=\"");
  out.integer(n);
  out.text("\">\n<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n");
  for (const Point3& p : mesh.points) write_xyz(out, p);
  out.text("</DataArray>\n</Points>\n<Cells>\n<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n");
  for (long long t = 0; t < n; ++t) {
    TextWriter::Line line = out.line(3);
    const auto [a, b, c] = mesh.triangles[static_cast<std::size_t>(t)];
    line.integer(a);
    line.next_integer(b);
    line.next_integer(c);
    line.end_line();
  }
  out.text("</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n");
  for (long long t = 0; t < n; ++t) {
    out.integer(3 * (t + 1));
    out.end_line();
  }
  out.text("</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n");
  for (long long t = 0; t < n; ++t) out.text("5\n");
  out.text("</DataArray>\n</Cells>\n<CellData Scalars=\"facet_marker\">\n"
           "<DataArray type=\"Int32\" Name=\"facet_marker\" format=\"ascii\">\n");
  for (long long t = 0; t < n; ++t) {
    out.integer(mesh.facet_marker[mesh.triangle_facet[t]]);
    out.end_line();
  }
  out.text("</DataArray>\n</CellData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n");
  out.finish();
}

}  // namespace deltri
