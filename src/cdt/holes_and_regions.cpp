#include "cdt/holes_and_regions.h"

#include "cdt/flood.h"
#include "geometry/hilbert.h"
#include "mesh/operations.h"
#include "mesh/remove_triangles.h"
#include "mesh/subsegments.h"

namespace deltri {

namespace {

bool constrained(const Mesh& mesh, EdgeRef e) {
  return mesh.has_subsegments() && mesh.subseg.has(e);
}

// Whether any edge around org(from) carries a subsegment: then the vertex sits on a segment and
// which side a point there belongs to is ambiguous.
bool touches_subsegment(const Mesh& mesh, EdgeRef from) {
  EdgeRef e = from;
  do {
    if (constrained(mesh, e) || constrained(mesh, lprev(e))) return true;
    e = mesh.onext(e);
  } while (e != kNone && e != from);
  for (e = from; mesh.link[e] != kNone && (e = lnext(mesh.link[e])) != from;)
    if (constrained(mesh, e) || constrained(mesh, lprev(e))) return true;
  return false;
}

// A hole point on subsegment e whose input segment does not pass through it: snapping (a vertex a
// few ulps off the segment placed on it) bent the chain onto the point, and the point's side is
// the one the input segment puts it on. The triangle on that side, or kNone if the point lies on
// the input segment itself (ambiguous) or nothing is there.
TriangleId side_of_input_segment(const Mesh& mesh, Predicates& pred, EdgeRef e, const Point& h,
                                 std::span<const Pslg::Segment> input) {
  const std::uint32_t seg = mesh.subsegments[mesh.subseg[e]].segment;
  if (seg >= input.size()) return kNone;
  const Point& a = mesh.point(VertexId{input[seg].a});
  const Point& b = mesh.point(VertexId{input[seg].b});
  const double side = pred.orient2d(a, b, h);
  if (side == 0) return kNone;
  const Point& p = mesh.point(mesh.org(e));
  const Point& q = mesh.point(mesh.dest(e));
  const bool along = (q.x - p.x) * (b.x - a.x) + (q.y - p.y) * (b.y - a.y) > 0;
  if ((side > 0) == along) return triangle_of(e);  // e's triangle lies to its left
  return mesh.link[e] == kNone ? kNone : triangle_of(mesh.link[e]);
}

// The triangle a hole point infects, or kNone (the point is then reported).
// Which of the triangles at an edge or vertex does not matter: without a subsegment there, the
// flood reaches all of them.
TriangleId hole_triangle(const Mesh& mesh, Predicates& pred, const Location& at, const Point& h,
                         std::span<const Pslg::Segment> input) {
  switch (at.status) {
    case LocateStatus::InTriangle:
      return triangle_of(at.edge);
    case LocateStatus::OnEdge:
      return constrained(mesh, at.edge) ? side_of_input_segment(mesh, pred, at.edge, h, input) : triangle_of(at.edge);
    case LocateStatus::OnVertex:
      return touches_subsegment(mesh, at.edge) ? kNone : triangle_of(at.edge);
    case LocateStatus::Outside:
      break;
  }
  return kNone;
}

// Where each point lies, in the points' order. The points are located along a Hilbert curve, each
// walk starting where the last one ended, so that a thousand holes cost a thousand short walks
// rather than a thousand walks across the mesh. A location depends only on the point (a walk that
// cannot decide ends in locate's scan), so the order changes no result.
std::vector<Location> locate_all(const Mesh& mesh, Predicates& pred, std::span<const Point> points) {
  std::vector<Location> where(points.size());
  EdgeRef hint = kNone;
  for (const std::uint32_t i : hilbert_order(points)) {
    where[i] = locate(mesh, pred, points[i], hint);
    if (where[i].status != LocateStatus::Outside) hint = where[i].edge;
  }
  return where;
}

std::vector<TriangleId> hull_seeds(const Mesh& mesh) {
  std::vector<TriangleId> seeds;
  for (EdgeRef e{0}; e < mesh.corner.size(); ++e)
    if (mesh.corner[e] != kNone && mesh.link[e] == kNone && !constrained(mesh, e))
      seeds.push_back(triangle_of(e));
  return seeds;
}

}  // namespace

HoleReport carve_holes(Mesh& mesh, Predicates& pred, const std::vector<Point>& holes, bool keep_convex_hull,
                       std::span<const Pslg::Segment> input_segments) {
  HoleReport report;
  std::vector<TriangleId> seeds;
  if (!keep_convex_hull) seeds = hull_seeds(mesh);
  // Locate every hole before anything is deleted, so that the flood starts from the mesh the
  // segments made (locate itself copes with non-convex meshes by its scan).
  const std::vector<Location> where = locate_all(mesh, pred, holes);
  for (std::size_t i = 0; i < holes.size(); ++i) {
    const Location& at = where[i];
    if (at.status == LocateStatus::Outside) {
      report.outside.push_back(i);
      continue;
    }
    const TriangleId t = hole_triangle(mesh, pred, at, holes[i], input_segments);
    if (t == kNone) report.on_segment.push_back(i);
    else seeds.push_back(t);
  }
  std::vector<std::uint32_t> infected(mesh.triangle_slots(), 0);
  const std::vector<TriangleId> exterior = flood(mesh, std::move(seeds), infected, 1);
  remove_triangles(mesh, exterior);
  report.triangles_removed = exterior.size();
  report.subsegments_removed = drop_unused_subsegments(mesh);
  mesh.compact_triangles();
  return report;
}

namespace {

void add_region_attribute(Mesh& mesh) {
  const int old = mesh.num_triangle_attributes;
  const std::size_t n = mesh.triangle_slots();
  std::vector<double> widened(n * (old + 1), 0.0);
  for (std::size_t t = 0; t < n; ++t)
    for (int k = 0; k < old; ++k) widened[t * (old + 1) + k] = mesh.triangle_attributes[t * old + k];
  mesh.triangle_attributes = std::move(widened);
  mesh.num_triangle_attributes = old + 1;
}

}  // namespace

RegionReport spread_regions(Mesh& mesh, Predicates& pred, const std::vector<Pslg::Region>& regions,
                            bool attributes, bool area_bounds, std::span<const Pslg::Segment> input_segments) {
  RegionReport report;
  if (attributes) add_region_attribute(mesh);
  if (area_bounds && mesh.area_bound.size() != mesh.triangle_slots())
    mesh.area_bound.assign(mesh.triangle_slots(), -1.0);
  if (!attributes && !area_bounds) return report;
  // Find all seeds first: locating is read-only, flooding writes only attributes.
  std::vector<Point> points;
  for (const Pslg::Region& r : regions) points.push_back(r.at);
  const std::vector<Location> where = locate_all(mesh, pred, points);
  std::vector<TriangleId> starts;
  for (std::size_t i = 0; i < regions.size(); ++i) {
    // The same rule as for hole points.
    starts.push_back(hole_triangle(mesh, pred, where[i], points[i], input_segments));
    if (starts.back() != kNone) continue;
    if (where[i].status == LocateStatus::Outside) report.outside.push_back(i);
    else report.on_segment.push_back(i);
  }
  std::vector<std::uint32_t> visited(mesh.triangle_slots(), 0);
  const int stride = mesh.num_triangle_attributes;
  for (std::uint32_t i = 0; i < regions.size(); ++i) {
    if (starts[i] == kNone) continue;
    for (const TriangleId t : flood(mesh, {starts[i]}, visited, i + 1)) {
      if (attributes) mesh.triangle_attributes[t * stride + stride - 1] = regions[i].attribute;
      if (area_bounds) mesh.area_bound[t] = regions[i].max_area;
    }
  }
  return report;
}

}  // namespace deltri
