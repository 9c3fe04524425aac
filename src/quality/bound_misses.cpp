#include "quality/bound_misses.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <numbers>
#include <vector>

namespace deltri {
namespace {

// Measured in doubles, with a relative margin of 1e-12 so that a triangle refinement judged good
// by the same bound in its own rounding is not counted for a last-bit difference.
constexpr double kMargin = 1e-12;

double length(const Point& a, const Point& b) { return std::hypot(b.x - a.x, b.y - a.y); }

double angle_at(const Point& a, const Point& b, const Point& c) {
  const double ux = b.x - a.x, uy = b.y - a.y, vx = c.x - a.x, vy = c.y - a.y;
  return std::atan2(std::fabs(ux * vy - uy * vx), ux * vx + uy * vy) * (180.0 / std::numbers::pi);
}

bool misses_angle(const Mesh& m, TriangleId t, double bound) {
  if (bound <= 0.0) return false;
  const Point &a = m.points[m.corner[3 * t]], &b = m.points[m.corner[3 * t + 1]], &c = m.points[m.corner[3 * t + 2]];
  return std::min({angle_at(a, b, c), angle_at(b, c, a), angle_at(c, a, b)}) < bound * (1.0 - kMargin);
}

bool misses_size(const Mesh& m, TriangleId t, const BoundRequest& r) {
  const Point &a = m.points[m.corner[3 * t]], &b = m.points[m.corner[3 * t + 1]], &c = m.points[m.corner[3 * t + 2]];
  const double area = 0.5 * std::fabs((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
  if (r.max_area > 0.0 && area > r.max_area * (1.0 + kMargin)) return true;
  if (r.area_bounds && m.area_bound.size() == m.triangle_slots() && m.area_bound[t] > 0.0 &&
      area > m.area_bound[t] * (1.0 + kMargin))
    return true;
  const double longest = std::max({length(a, b), length(b, c), length(c, a)});
  return r.max_edge_length > 0.0 && longest > r.max_edge_length * (1.0 + kMargin);
}

bool at_precision_limit(const Mesh& m, TriangleId t) {
  double shortest = INFINITY, largest = 0.0;
  for (int i = 0; i < 3; ++i) {
    const Point& p = m.points[m.corner[3 * t + i]];
    const Point& q = m.points[m.corner[3 * t + (i + 1) % 3]];
    shortest = std::min(shortest, length(p, q));
    largest = std::max({largest, std::fabs(p.x), std::fabs(p.y)});
  }
  largest = std::max(largest, DBL_MIN);
  return shortest <= kPrecisionUlps * (std::nextafter(largest, INFINITY) - largest);
}

// The segments at each vertex: direction angles and input segment numbers.
struct Spoke {
  double direction;  // radians, atan2
  VertexId to;
  std::uint32_t segment;
};

struct SegmentVertices {
  std::vector<std::vector<Spoke>> spokes;               // per vertex, by direction
  std::vector<char> on_segment;                         // per vertex
  std::vector<std::vector<VertexId>> segment_vertices;  // per input segment: the vertices on it
};

SegmentVertices collect_spokes(const Mesh& m) {
  SegmentVertices s;
  s.spokes.resize(m.vertex_count());
  s.on_segment.assign(m.vertex_count(), 0);
  if (!m.has_subsegments()) return s;
  for (TriangleId t = 0; t < m.triangle_slots(); ++t) {
    if (!m.is_live(t)) continue;
    for (EdgeRef e = 3 * t; e < 3 * t + 3; ++e) {
      if (m.subseg[e] == kNone || (m.link[e] != kNone && m.link[e] < e)) continue;
      const VertexId a = m.org(e), b = m.dest(e);
      const std::uint32_t seg = m.subsegments[m.subseg[e]].segment;
      const Point &p = m.points[a], &q = m.points[b];
      s.spokes[a].push_back({std::atan2(q.y - p.y, q.x - p.x), b, seg});
      s.spokes[b].push_back({std::atan2(p.y - q.y, p.x - q.x), a, seg});
      s.on_segment[a] = s.on_segment[b] = 1;
      if (seg == kNone) continue;
      if (seg >= s.segment_vertices.size()) s.segment_vertices.resize(seg + 1);
      s.segment_vertices[seg].push_back(a);
      s.segment_vertices[seg].push_back(b);
    }
  }
  for (auto& list : s.spokes)
    std::sort(list.begin(), list.end(), [](const Spoke& x, const Spoke& y) { return x.direction < y.direction; });
  return s;
}

// A vertex deltri made where input segments cross or overlap.
bool repaired_vertex(const Mesh& m, const SegmentVertices& s, VertexId v) {
  if (m.kind[v] == VertexKind::Input) return false;
  for (const Spoke& k : s.spokes[v])
    if (k.segment != s.spokes[v].front().segment) return true;
  return false;
}

// The reach of the narrow angles at v: 0 when no two angularly consecutive segments at v meet at
// less than the -q bound, otherwise the squared distance from v to the farthest vertex on an
// input segment forming such an angle (the region refinement must shape around the angle).
double narrow_reach2(const Mesh& m, const SegmentVertices& s, VertexId v, double bound_deg) {
  const auto& list = s.spokes[v];
  if (list.size() < 2 || bound_deg <= 0.0) return 0.0;
  const double bound = bound_deg * std::numbers::pi / 180.0;
  const Point& o = m.points[v];
  const auto distance2 = [&](VertexId w) {
    const double dx = m.points[w].x - o.x, dy = m.points[w].y - o.y;
    return dx * dx + dy * dy;
  };
  const auto farthest2 = [&](const Spoke& k) {
    double d2 = distance2(k.to);
    if (k.segment != kNone && k.segment < s.segment_vertices.size())
      for (VertexId w : s.segment_vertices[k.segment]) d2 = std::max(d2, distance2(w));
    return d2;
  };
  double reach2 = 0.0;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const Spoke& a = list[i];
    const Spoke& b = list[(i + 1) % list.size()];
    double gap = b.direction - a.direction;
    if (i + 1 == list.size()) gap += 2 * std::numbers::pi;
    if (gap < bound) reach2 = std::max({reach2, farthest2(a), farthest2(b)});
  }
  return reach2;
}

bool within(const Mesh& m, VertexId apex, double reach2, TriangleId t) {
  const Point& o = m.points[apex];
  for (int i = 0; i < 3; ++i) {
    const Point& p = m.points[m.corner[3 * t + i]];
    const double dx = p.x - o.x, dy = p.y - o.y;
    if (dx * dx + dy * dy > reach2 * (1.0 + 1e-9)) return false;
  }
  return true;
}

// Marks (with `mark`) the missing triangles that touch a vertex `chosen` accepts, and those
// reached from them through edge-adjacent missing triangles within that vertex's narrow reach.
template <class Chosen>
void mark_near(const Mesh& m, const SegmentVertices& s, double bound_deg, const std::vector<char>& missing,
               std::vector<char>& cause, char mark, Chosen chosen) {
  std::vector<std::vector<TriangleId>> at(m.vertex_count());
  for (TriangleId t = 0; t < m.triangle_slots(); ++t)
    if (m.is_live(t) && missing[t] && !cause[t])
      for (int i = 0; i < 3; ++i)
        if (chosen(m.corner[3 * t + i])) at[m.corner[3 * t + i]].push_back(t);
  for (VertexId v = 0; v < m.vertex_count(); ++v) {
    if (at[v].empty()) continue;
    for (TriangleId t : at[v]) cause[t] = mark;
    const double reach2 = narrow_reach2(m, s, v, bound_deg);
    if (reach2 <= 0.0) continue;
    std::vector<TriangleId> stack = at[v];
    while (!stack.empty()) {
      const TriangleId t = stack.back();
      stack.pop_back();
      for (EdgeRef e = 3 * t; e < 3 * t + 3; ++e) {
        if (m.link[e] == kNone) continue;
        const TriangleId n = m.link[e] / 3;
        if (!missing[n] || cause[n] || !within(m, v, reach2, n)) continue;
        cause[n] = mark;
        stack.push_back(n);
      }
    }
  }
}

}  // namespace

BoundMisses count_bound_misses(const Mesh& m, const BoundRequest& r) {
  BoundMisses out;
  std::vector<char> missing(m.triangle_slots(), 0);
  for (TriangleId t = 0; t < m.triangle_slots(); ++t) {
    if (!m.is_live(t)) continue;
    const bool angle = misses_angle(m, t, r.min_angle_deg), size = misses_size(m, t, r);
    out.below_angle += angle;
    out.above_size += size;
    missing[t] = angle || size;
    out.total += missing[t];
  }
  if (out.total == 0) return out;
  enum : char { kNoCause, kSmallAngle, kRepaired, kPrecision, kLimits, kOther };
  std::vector<char> cause(m.triangle_slots(), kNoCause);
  const SegmentVertices s = collect_spokes(m);
  mark_near(m, s, r.min_angle_deg, missing, cause, kSmallAngle, [&](VertexId v) {
    return m.kind[v] == VertexKind::Input && narrow_reach2(m, s, v, r.min_angle_deg) > 0.0;
  });
  mark_near(m, s, r.min_angle_deg, missing, cause, kRepaired, [&](VertexId v) { return repaired_vertex(m, s, v); });
  for (TriangleId t = 0; t < m.triangle_slots(); ++t) {
    if (!m.is_live(t) || !missing[t] || cause[t]) continue;
    bool touches_segment = false;
    for (int i = 0; i < 3; ++i) touches_segment = touches_segment || s.on_segment[m.corner[3 * t + i]];
    cause[t] = at_precision_limit(m, t)                              ? kPrecision
               : r.steiner_limited || (r.segments_kept_whole && touches_segment) ? kLimits
                                                                     : kOther;
  }
  for (TriangleId t = 0; t < m.triangle_slots(); ++t) {
    if (!m.is_live(t) || !missing[t]) continue;
    out.small_input_angle += cause[t] == kSmallAngle;
    out.repaired_input += cause[t] == kRepaired;
    out.double_precision += cause[t] == kPrecision;
    out.steiner_limits += cause[t] == kLimits;
    out.other += cause[t] == kOther;
  }
  return out;
}

}  // namespace deltri
