#include "refine/clusters.h"

#include <cmath>
#include <cstdint>
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

// Turns counter-clockwise around the origin of subsegment edge e, calling visit(f) for the edge f
// leaving it in each triangle passed, to the next subsegment there: returns the edge that carries
// it (from its far end back to the origin), or kNone when the turn reaches an edge of the mesh that
// is no subsegment (a boundary left unconstrained) or comes full circle.
template <class Visit>
EdgeRef turn_to_next_subsegment(const Mesh& mesh, EdgeRef e, Visit&& visit) {
  for (EdgeRef f = e;;) {
    visit(f);
    const EdgeRef back = lprev(f);  // from the apex of f's triangle back to the origin
    if (has_subsegment(mesh, back)) return back;
    f = mesh.link[back];
    if (f == kNone || f == e) return kNone;
  }
}

// The angle inside the domain from subsegment edge e counter-clockwise around its origin to the
// next subsegment there, the sum of the triangles' angles; HUGE_VAL when there is none.
double wedge_to_next_subsegment(const Mesh& mesh, EdgeRef e) {
  double angle = 0.0;
  const EdgeRef back = turn_to_next_subsegment(mesh, e, [&](EdgeRef f) { angle += angle_at_origin(mesh, f); });
  return back == kNone ? HUGE_VAL : angle;
}

// Where the angle counter-clockwise from direction u to direction w lies against a right angle,
// read off the signs of their cross and dot products where both are clear of zero by kClear times
// |u| |w|, that is where the angle is about kClear radians or more from 0, pi/2, pi and 3 pi/2. Near
// those, and where the squares overflow or underflow, the answer is Near.
enum class RightAngle { Below, Above, Near };
constexpr double kClear = 1e-9;

RightAngle against_right_angle(double ux, double uy, double wx, double wy) {
  const double norms = (ux * ux + uy * uy) * (wx * wx + wy * wy);
  if (!(norms > 1e-280 && norms < 1e280)) return RightAngle::Near;
  const double cross = ux * wy - uy * wx, dot = ux * wx + uy * wy;
  const double least = kClear * kClear * norms;
  if (cross * cross <= least) return RightAngle::Near;
  if (cross < 0.0) return RightAngle::Above;  // beyond pi
  if (dot * dot <= least) return RightAngle::Near;
  return dot > 0.0 ? RightAngle::Below : RightAngle::Above;
}

// Beyond this many triangles the sum below is not assumed to stay within kClear of the angle.
constexpr std::uint32_t kLongTurn = 10000;

// wedge_to_next_subsegment(mesh, e) < kAcute, mostly without its atan2 per triangle: the wedge is the
// angle from e to the next subsegment (mod 2 pi), and the sum of per-triangle angles differs from it
// by rounding, about 1e-15 a triangle, so where against_right_angle decides, the sum falls on the
// same side of kAcute. Only wedges within about kClear of a right angle are added up.
bool acute_wedge(const Mesh& mesh, EdgeRef e) {
  std::uint32_t triangles = 0;
  const EdgeRef back = turn_to_next_subsegment(mesh, e, [&](EdgeRef) { ++triangles; });
  if (back == kNone) return false;  // no wedge: wedge_to_next_subsegment's HUGE_VAL
  if (triangles < kLongTurn) {
    const Point& o = mesh.point(mesh.org(e));
    const Point& d = mesh.point(mesh.dest(e));
    const Point& x = mesh.point(mesh.org(back));
    const RightAngle side = against_right_angle(d.x - o.x, d.y - o.y, x.x - o.x, x.y - o.y);
    if (side != RightAngle::Near) return side == RightAngle::Below;
  }
  return wedge_to_next_subsegment(mesh, e) < kAcute;
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
      if (degree[v] < 3) ++degree[v];
  }
  corner_.assign(mesh.vertex_count(), false);
  for (VertexId v{0}; v < mesh.vertex_count(); ++v) {
    apex_[v] = degree[v] >= 2;
    corner_[v] = degree[v] == 2;
  }
  shells_.assign(mesh.vertex_count(), false);
  for (EdgeRef e{0}; e < mesh.corner.size(); ++e) {
    if (mesh.corner[e] == kNone || !has_subsegment(mesh, e)) continue;
    const VertexId v = mesh.org(e);
    if (apex_[v] && !shells_[v]) shells_[v] = acute_wedge(mesh, e);
  }
}

SegmentApices SegmentApices::of_vertices(const std::vector<VertexId>& vertices) const {
  SegmentApices part;
  part.apex_.assign(vertices.size(), false);
  part.shells_.assign(vertices.size(), false);
  part.corner_.assign(vertices.size(), false);
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    if (is_apex(vertices[i])) part.apex_[i] = true;
    if (uses_shells(vertices[i])) part.shells_[i] = true;
    if (is_two_segment_corner(vertices[i])) part.corner_[i] = true;
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
