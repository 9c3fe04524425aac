#include "surface/check_surface.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <tuple>
#include <utility>

#include "geometry/collinear3.h"
#include "geometry/predicates.h"
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

// Whether facet f's mesh covers the midpoint of the piece a-b of one of its segments (global
// vertex ids), by exact orientation tests in its plane coordinates: a piece that is no edge of the
// facet is right only where the facet's hole points carved the region around it away.
bool covers_piece(const SurfaceMesh& m, std::uint32_t f, std::uint32_t a, std::uint32_t b) {
  const Mesh& mesh = m.facet_meshes[f];
  const std::vector<std::uint32_t>& global = m.facet_vertex[f];
  std::uint32_t la = kNone, lb = kNone;
  for (std::uint32_t v = 0; v < global.size(); ++v) {
    if (global[v] == a) la = v;
    if (global[v] == b) lb = v;
  }
  if (la == kNone || lb == kNone) return true;  // the facet lost a vertex of its own segment: a fault
  const Point& pa = mesh.points[la];
  const Point& pb = mesh.points[lb];
  const Point mid{pa.x + 0.5 * (pb.x - pa.x), pa.y + 0.5 * (pb.y - pa.y)};
  Predicates pred;
  for (TriangleId t{0}; t < mesh.triangle_slots(); ++t) {
    if (!mesh.is_live(t)) continue;
    const auto [x, y, z] = mesh.corners(t);
    const Point& px = mesh.points[x];
    const Point& py = mesh.points[y];
    const Point& pz = mesh.points[z];
    if (pred.orient2d(px, py, mid) >= 0 && pred.orient2d(py, pz, mid) >= 0 && pred.orient2d(pz, px, mid) >= 0) return true;
  }
  return false;
}

// A shared subsegment must be an edge in every facet holding its input segment (unless that
// facet's hole points carved the piece away): the surface's subsegments are the union over the
// facets, so each is looked up in each facet's own edges.
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
      if (!facet_edges[f].count(key) && covers_piece(m, f, s.a, s.b))
        fault(c, "subsegment " + std::to_string(s.a + 1) + "-" + std::to_string(s.b + 1) + " is no edge of facet " +
                     std::to_string(f + 1) + ", which holds its segment");
  }
}

// The surface in space, from its triangles alone: two distinct vertices of triangles at one point
// are a crack (facets meeting there along different copies of their border, each border an edge
// of one triangle where the surface should be joined).
void check_cracks(const SurfaceMesh& m, SurfaceCheck& c) {
  std::vector<char> used(m.points.size(), 0);
  for (const std::array<std::uint32_t, 3>& t : m.triangles)
    for (std::uint32_t v : t) used[v] = 1;
  std::vector<std::uint32_t> order;
  for (std::uint32_t v = 0; v < m.points.size(); ++v)
    if (used[v]) order.push_back(v);
  const auto key = [&](std::uint32_t v) {
    const Point3& p = m.points[v];
    return std::tuple{p.x + 0.0, p.y + 0.0, p.z + 0.0};
  };
  std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return key(a) < key(b); });
  for (std::size_t i = 1; i < order.size(); ++i)
    if (key(order[i - 1]) == key(order[i]))
      fault(c, "vertices " + std::to_string(std::min(order[i - 1], order[i]) + 1) + " and " +
                   std::to_string(std::max(order[i - 1], order[i]) + 1) +
                   " of triangles lie at one point: the surface is cracked there");
}

void check_planar(const SurfaceMesh& m, SurfaceCheck& c) {
  Predicates pred;
  for (std::size_t t = 0; t < m.triangle_count(); ++t) {
    const FacetPlane& plane = m.planes[m.triangle_facet[t]];
    const Point3& a = m.points[m.triangles[t][0]];
    const Point3& b = m.points[m.triangles[t][1]];
    const Point3& d = m.points[m.triangles[t][2]];
    const double off = std::max({std::abs(plane.distance(a)), std::abs(plane.distance(b)), std::abs(plane.distance(d))});
    if (off > kPlanarTolerance * plane.diameter)
      fault(c, "triangle " + std::to_string(t + 1) + " lies off the plane of facet " +
                   std::to_string(m.triangle_facet[t] + 1));
    // Exactly: the length of the cross product underflowed to 0 for triangles of size 1e-148 (a unit
    // cube meshed scaled by 2^-492 beside a point at 1e148).
    if (collinear3(pred, a, b, d)) fault(c, "triangle " + std::to_string(t + 1) + " has zero area in space");
  }
}

}  // namespace

std::string SurfaceCheck::summary() const {
  std::string text = "  " + std::to_string(faults) + (faults == 1 ? " fault" : " faults") + " in the surface mesh\n";
  for (const std::string& e : examples) text += "  " + e + "\n";
  return text;
}

std::string SurfaceCheck::one_line() const {
  std::string text = std::to_string(faults) + (faults == 1 ? " fault" : " faults");
  if (!examples.empty()) text += ", first: " + examples.front();
  return text;
}

SurfaceCheck check_surface(const SurfaceMesh& mesh) {
  SurfaceCheck c;
  check_facets(mesh, c);
  check_conforming(mesh, c);
  check_planar(mesh, c);
  check_cracks(mesh, c);
  return c;
}

}  // namespace deltri
