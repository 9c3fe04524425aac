#include "refine/clusters.h"

#include <cmath>
#include <numbers>

namespace deltri {
namespace {

constexpr double kSixtyDegrees = std::numbers::pi / 3.0 * (1.0 + 1e-12);
// Right angles computed with rounding count as right, not acute.
constexpr double kAcute = std::numbers::pi / 2.0 * (1.0 - 1e-12);

bool has_subsegment(const Mesh& mesh, EdgeRef e) { return mesh.subseg.has(e); }

// The angle at org(e) of triangle_of(e), between e and the reverse of lprev(e).
double angle_at_origin(const Mesh& mesh, EdgeRef e) {
  const Point& o = mesh.point(mesh.org(e));
  const Point& d = mesh.point(mesh.dest(e));
  const Point& a = mesh.point(mesh.apex(e));
  const double ux = d.x - o.x, uy = d.y - o.y, vx = a.x - o.x, vy = a.y - o.y;
  return std::atan2(ux * vy - uy * vx, ux * vx + uy * vy);
}

// Turns counter-clockwise (ccw) or clockwise from edge e around its origin to the next edge that
// carries a subsegment, adding up the angle. kNone when the boundary or `stop` comes first.
EdgeRef next_spoke(const Mesh& mesh, EdgeRef e, bool ccw, EdgeRef stop, double& angle) {
  angle = 0.0;
  EdgeRef f = e;
  while (true) {
    EdgeRef next;
    if (ccw) {
      angle += angle_at_origin(mesh, f);
      next = mesh.link[lprev(f)];
      if (next == kNone) return kNone;
    } else {
      const EdgeRef twin = mesh.link[f];
      if (twin == kNone) return kNone;
      next = lnext(twin);
      angle += angle_at_origin(mesh, next);
    }
    if (next == stop || next == e) return kNone;
    if (has_subsegment(mesh, next)) return next;
    f = next;
  }
}

// The angle inside the domain from subsegment edge e counter-clockwise around its origin to the
// next subsegment there; HUGE_VAL when the turn reaches an edge of the mesh that is no
// subsegment (a boundary left unconstrained) or comes full circle.
double wedge_to_next_subsegment(const Mesh& mesh, EdgeRef e) {
  double angle = 0.0;
  for (EdgeRef f = e;;) {
    angle += angle_at_origin(mesh, f);
    const EdgeRef back = lprev(f);  // from the apex of f's triangle back to the origin
    if (has_subsegment(mesh, back)) return angle;
    f = mesh.link[back];
    if (f == kNone || f == e) return HUGE_VAL;
  }
}

}  // namespace

SegmentApices::SegmentApices(const Mesh& mesh) : apex_(mesh.vertex_count(), false) {
  std::vector<unsigned char> degree(mesh.vertex_count(), 0);
  if (!mesh.has_subsegments()) return;
  for (EdgeRef e{0}; e < mesh.corner.size(); ++e) {
    if (mesh.corner[e] == kNone || !mesh.subseg.has(e)) continue;
    // Count each subsegment once: from the edge whose twin is missing or has a larger id.
    const EdgeRef twin = mesh.link[e];
    if (twin != kNone && twin < e) continue;
    for (VertexId v : {mesh.org(e), mesh.dest(e)})
      if (degree[v] < 2) ++degree[v];
  }
  for (VertexId v{0}; v < mesh.vertex_count(); ++v) apex_[v] = degree[v] >= 2;
  shells_.assign(mesh.vertex_count(), false);
  for (EdgeRef e{0}; e < mesh.corner.size(); ++e) {
    if (mesh.corner[e] == kNone || !has_subsegment(mesh, e) || !apex_[mesh.org(e)]) continue;
    if (wedge_to_next_subsegment(mesh, e) < kAcute) shells_[mesh.org(e)] = true;
  }
}

SegmentApices SegmentApices::of_vertices(const std::vector<VertexId>& vertices) const {
  SegmentApices part;
  part.apex_.assign(vertices.size(), false);
  part.shells_.assign(vertices.size(), false);
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    if (is_apex(vertices[i])) part.apex_[i] = true;
    if (uses_shells(vertices[i])) part.shells_[i] = true;
  }
  return part;
}

Cluster subsegment_cluster(const Mesh& mesh, EdgeRef from_apex) {
  Cluster cluster;
  cluster.members.push_back(from_apex);
  cluster.min_separation = HUGE_VAL;
  EdgeRef last_ccw = from_apex;
  for (bool ccw : {true, false}) {
    EdgeRef at = from_apex;
    // A sweep that comes full circle stops where it began (counter-clockwise) or where the
    // counter-clockwise sweep ended (clockwise), so no member is counted twice.
    const EdgeRef stop = ccw ? from_apex : last_ccw;
    while (true) {
      double angle = 0.0;
      const EdgeRef spoke = next_spoke(mesh, at, ccw, stop, angle);
      if (spoke == kNone || angle > kSixtyDegrees) break;
      cluster.members.push_back(spoke);
      cluster.min_separation = std::min(cluster.min_separation, angle);
      at = spoke;
      if (ccw) last_ccw = spoke;
    }
  }
  return cluster;
}

}  // namespace deltri
