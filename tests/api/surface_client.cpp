// A C++ client of deltri::mesh_surface (deltri/deltri.hpp), for tests/api/surface_clients.py: the
// same input file and printout as surface_client.c, through the C++ API's value types.
//   surface_client_cpp SWITCHES INPUT.flat
#include <cstdio>
#include <fstream>
#include <iostream>

#include "deltri/deltri.hpp"

namespace {

deltri::Facets read(std::istream& in) {
  deltri::Facets facets;
  std::size_t points = 0, facet_count = 0;
  bool markers = false;
  in >> points >> markers;
  for (std::size_t k = 0; k < points; ++k) {
    double x, y, z;
    in >> x >> y >> z;
    facets.points.insert(facets.points.end(), {x, y, z});
    if (markers) facets.point_markers.emplace_back(), in >> facets.point_markers.back();
  }
  in >> facet_count;
  for (std::size_t k = 0; k < facet_count; ++k) {
    deltri::Facet f;
    std::size_t polygons = 0, holes = 0;
    in >> polygons >> holes >> f.marker;
    f.polygons.resize(polygons);
    for (auto& polygon : f.polygons) {
      std::size_t corners = 0;
      in >> corners;
      polygon.resize(corners);
      for (int& c : polygon) in >> c;
    }
    f.holes.resize(3 * holes);
    for (double& h : f.holes) in >> h;
    facets.facets.push_back(std::move(f));
  }
  if (!in) throw std::runtime_error("bad input file");
  return facets;
}

void print(const deltri::Surface& s) {
  std::printf("points %d %d\n", s.point_count, s.point_markers.empty() ? 0 : 1);
  for (int k = 0; k < s.point_count; ++k) {
    std::printf("%.17g %.17g %.17g", s.points[3 * k], s.points[3 * k + 1], s.points[3 * k + 2]);
    if (!s.point_markers.empty()) std::printf(" %d", s.point_markers[k]);
    std::printf("\n");
  }
  std::printf("triangles %d\n", s.triangle_count);
  for (int k = 0; k < s.triangle_count; ++k)
    std::printf("%d %d %d %.17g %d\n", s.triangles[3 * k], s.triangles[3 * k + 1], s.triangles[3 * k + 2],
                s.triangle_attributes[k], s.triangle_facets[k]);
  std::printf("edges %d %d\n", s.edge_count, s.edge_markers.empty() ? 0 : 1);
  for (int k = 0; k < s.edge_count; ++k) {
    std::printf("%d %d", s.edges[2 * k], s.edges[2 * k + 1]);
    if (!s.edge_markers.empty()) std::printf(" %d", s.edge_markers[k]);
    std::printf("\n");
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: surface_client_cpp SWITCHES INPUT.flat\n");
    return 1;
  }
  std::ifstream file(argv[2]);
  const deltri::Facets facets = read(file);
  try {
    print(deltri::mesh_surface(facets, argv[1]));
  } catch (const deltri::Error& e) {
    std::printf("status %d %s\n", e.code(), e.what());
  }
  return 0;
}
