#include "surface/check_surface.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <utility>

#include "quality/check_mesh.h"

namespace deltri {
namespace {

constexpr std::size_t kExamples = 8;

using EdgeSet = std::set<std::pair<std::uint32_t, std::uint32_t>>;

void fault(SurfaceCheck& c, const std::string& what) {
  ++c.faults;
  if (c.examples.size() < kExamples) c.examples.push_back(what);
}

void check_facets(const SurfaceMesh& m, SurfaceCheck& c) {
  for (std::size_t f = 0; f < m.facet_meshes.size(); ++f) {
    const Mesh& mesh = m.facet_meshes[f];
    const CheckReport r = check_mesh(mesh, CheckOptions{});
    if (!r.ok()) fault(c, "facet " + std::to_string(f + 1) + ": " + r.summary());
    for (EdgeRef e{0}; e < mesh.corner.size(); ++e)
      if (mesh.is_live(triangle_of(e)) && mesh.link[e] == kNone && (!mesh.has_subsegments() || !mesh.subseg.has(e)))
        fault(c, "facet " + std::to_string(f + 1) + ": a boundary edge of its mesh lies on no input segment");
  }
}

// A shared subsegment must be an edge in every facet holding its input segment: the surface's
// subsegments are the union over the facets, so each is looked up in each facet's own edges.
void check_conforming(const SurfaceMesh& m, SurfaceCheck& c) {
  std::vector<EdgeSet> facet_edges(m.facet_meshes.size());
  for (std::uint32_t f = 0; f < m.facet_meshes.size(); ++f) {
    const Mesh& mesh = m.facet_meshes[f];
    const std::vector<std::uint32_t>& global = m.facet_vertex[f];
    for (EdgeRef e{0}; e < mesh.corner.size(); ++e) {
      if (!mesh.is_live(triangle_of(e)) || !mesh.has_subsegments() || !mesh.subseg.has(e)) continue;
      const std::uint32_t a = global[mesh.org(e)], b = global[mesh.dest(e)];
      facet_edges[f].insert({std::min(a, b), std::max(a, b)});
    }
  }
  for (const SurfaceMesh::Edge& s : m.subsegments) {
    const std::pair<std::uint32_t, std::uint32_t> key{std::min(s.a, s.b), std::max(s.a, s.b)};
    for (std::uint32_t f : m.segment_facets[s.segment])
      if (!facet_edges[f].count(key))
        fault(c, "subsegment " + std::to_string(s.a + 1) + "-" + std::to_string(s.b + 1) + " is no edge of facet " +
                     std::to_string(f + 1) + ", which holds its segment");
  }
}

void check_planar(const SurfaceMesh& m, SurfaceCheck& c) {
  for (std::size_t t = 0; t < m.triangle_count(); ++t) {
    const FacetPlane& plane = m.planes[m.triangle_facet[t]];
    const Point3& a = m.points[m.triangles[t][0]];
    const Point3& b = m.points[m.triangles[t][1]];
    const Point3& d = m.points[m.triangles[t][2]];
    const double off = std::max({std::abs(plane.distance(a)), std::abs(plane.distance(b)), std::abs(plane.distance(d))});
    if (off > kPlanarTolerance * plane.diameter)
      fault(c, "triangle " + std::to_string(t + 1) + " lies off the plane of facet " +
                   std::to_string(m.triangle_facet[t] + 1));
    if (norm(cross(b - a, d - a)) == 0.0) fault(c, "triangle " + std::to_string(t + 1) + " has zero area in space");
  }
}

}  // namespace

std::string SurfaceCheck::summary() const {
  std::string text = "  " + std::to_string(faults) + (faults == 1 ? " fault" : " faults") + " in the surface mesh\n";
  for (const std::string& e : examples) text += "  " + e + "\n";
  return text;
}

SurfaceCheck check_surface(const SurfaceMesh& mesh) {
  SurfaceCheck c;
  check_facets(mesh, c);
  check_conforming(mesh, c);
  check_planar(mesh, c);
  return c;
}

}  // namespace deltri
