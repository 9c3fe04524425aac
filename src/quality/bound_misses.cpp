#include "quality/bound_misses.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <numbers>
#include <vector>

#include "util/prefetch.h"
#include "util/run_both.h"

namespace deltri {
namespace {

// Measured in doubles, with a relative margin of 1e-12 so that a triangle refinement judged good
// by the same bound in its own rounding is not counted for a last-bit difference.
constexpr double kMargin = 1e-12;

// Input angles under this are "small": the region near them is exempt (as in Triangle and in
// Miller, Pav and Walkington's analysis, refinement cannot be asked to do better there).
constexpr double kSmallInputAngle = 60.0;

double length(const Point& a, const Point& b) { return std::hypot(b.x - a.x, b.y - a.y); }

double angle_at(const Point& a, const Point& b, const Point& c) {
  const double ux = b.x - a.x, uy = b.y - a.y, vx = c.x - a.x, vy = c.y - a.y;
  return std::atan2(std::fabs(ux * vy - uy * vx), ux * vx + uy * vy) * (180.0 / std::numbers::pi);
}

// The angle test without atan2 where the answer is clear: the corner's angle is atan2(cross, dot),
// so with dot > 0 it is below `limit` degrees exactly when cross < tan(limit) dot. A relative gap
// of 1e-9, far beyond the rounding of either form, leaves only the near ties to atan2, so every
// answer is the one atan2 gives (most triangles of a refined mesh are clear of the bound).
struct AngleTest {
  static constexpr double kTiny = 1e-250;
  double limit = 0.0;  // degrees; 0: no angle bound
  double tangent = 0.0;
  explicit AngleTest(double bound)
      : limit(bound * (1.0 - kMargin)), tangent(std::tan(limit * (std::numbers::pi / 180.0))) {}
  // -1 below the limit, +1 not below, 0 a near tie.
  int clear_side(const Point& a, const Point& b, const Point& c) const {
    const double ux = b.x - a.x, uy = b.y - a.y, vx = c.x - a.x, vy = c.y - a.y;
    const double cross = std::fabs(ux * vy - uy * vx), dot = ux * vx + uy * vy;
    if (limit >= 89.0) return 0;
    if (!(dot > kTiny)) return dot < -kTiny ? 1 : 0;  // obtuse; or tiny, where products lose bits
    if (cross > tangent * dot * (1.0 + 1e-9)) return 1;
    if (cross < tangent * dot * (1.0 - 1e-9)) return -1;
    return 0;
  }
  bool below(const Point& a, const Point& b, const Point& c) const {
    const int side = clear_side(a, b, c);
    return side != 0 ? side < 0 : angle_at(a, b, c) < limit;
  }
};

bool misses_angle(const Point& a, const Point& b, const Point& c, const AngleTest& test) {
  if (test.limit <= 0.0) return false;
  return test.below(a, b, c) || test.below(b, c, a) || test.below(c, a, b);
}

bool misses_size(const Mesh& m, TriangleId t, const Point& a, const Point& b, const Point& c, const BoundRequest& r) {
  const double area = 0.5 * std::fabs((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
  if (r.size.max_area > 0.0 && area > r.size.max_area * (1.0 + kMargin)) return true;
  if (r.size.triangle_bounds && m.area_bound.size() == m.triangle_slots() && m.area_bound[t] > 0.0 &&
      area > m.area_bound[t] * (1.0 + kMargin))
    return true;
  if (r.size.max_edge_length <= 0.0) return false;
  const double longest = std::max({length(a, b), length(b, c), length(c, a)});
  return longest > r.size.max_edge_length * (1.0 + kMargin);
}

bool at_precision_limit(const Mesh& m, TriangleId t) {
  double shortest = INFINITY, largest = 0.0;
  for (int i = 0; i < 3; ++i) {
    const Point& p = m.points[m.corner[edge_of(t, i)]];
    const Point& q = m.points[m.corner[edge_of(t, (i + 1) % 3)]];
    shortest = std::min(shortest, length(p, q));
    largest = std::max({largest, std::fabs(p.x), std::fabs(p.y)});
  }
  largest = std::max(largest, DBL_MIN);
  return shortest <= kPrecisionUlps * (std::nextafter(largest, INFINITY) - largest);
}

// The segments at each vertex: direction angles and input segment numbers.
struct Spoke {
  double direction;  // radians, atan2, in (-pi, pi]
  VertexId to;
  std::uint32_t segment;
};

struct SegmentVertices {
  std::vector<std::vector<Spoke>> spokes;             // per vertex, by direction
  std::vector<std::vector<std::uint32_t>> segments;   // per vertex: the input segments it lies on
  std::vector<std::vector<VertexId>> junctions;       // per input segment: its vertices on other segments too
};

// The number after every input segment's: the first number a hull edge can take.
std::uint32_t first_hull_number(const Mesh& m) {
  std::uint32_t first = 0;
  for (const Subsegment& r : m.subsegments)
    if (r.a != kNone && r.segment != kNone) first = std::max(first, r.segment + 1);
  return first;
}

std::uint32_t root_of(std::vector<std::uint32_t>& parent, std::uint32_t x) {
  while (parent[x] != x) x = parent[x] = parent[parent[x]];
  return x;
}

// Pieces of the boundary that come from no input segment (the convex hull's edges, with -c or
// without -p) are numbered after the input segments, one number per hull edge: the pieces joined
// at vertices refinement put on them (not input vertices) form one edge. So a hull edge meets an
// input segment, or another hull edge, at a junction as two segments do, and the rules below
// explain the angles between them, as meshcheck's convex-hull mode and Triangle do.
void number_hull_edges(const Mesh& m, std::uint32_t first, SegmentVertices& s) {
  std::vector<std::uint32_t> parent;
  for (VertexId v{0}; v < m.vertex_count(); ++v)
    for (Spoke& k : s.spokes[v])
      if (k.segment == kNone && v < k.to) {  // each piece once, from its lower end
        k.segment = first + static_cast<std::uint32_t>(parent.size());
        parent.push_back(static_cast<std::uint32_t>(parent.size()));
        for (Spoke& back : s.spokes[k.to])
          if (back.to == v && back.segment == kNone) back.segment = k.segment;
      }
  if (parent.empty()) return;
  for (VertexId v{0}; v < m.vertex_count(); ++v) {
    if (m.kind[v] == VertexKind::Input) continue;
    std::uint32_t joined = kNone;
    for (const Spoke& k : s.spokes[v]) {
      if (k.segment < first) continue;
      if (joined == kNone) joined = k.segment - first;
      else parent[root_of(parent, k.segment - first)] = root_of(parent, joined);
    }
  }
  for (auto& list : s.spokes)
    for (Spoke& k : list)
      if (k.segment != kNone && k.segment >= first) k.segment = first + root_of(parent, k.segment - first);
}

SegmentVertices collect_spokes(const Mesh& m) {
  SegmentVertices s;
  s.spokes.resize(m.vertex_count());
  s.segments.resize(m.vertex_count());
  if (!m.has_subsegments()) return s;
  for (TriangleId t{0}; t < m.triangle_slots(); ++t) {
    if (!m.is_live(t)) continue;
    for (EdgeRef e : edges_of(t)) {
      if (!m.subseg.has(e) || (m.link[e] != kNone && m.link[e] < e)) continue;
      const VertexId a = m.org(e), b = m.dest(e);
      const std::uint32_t seg = m.subsegments[m.subseg[e]].segment;
      const Point &p = m.points[a], &q = m.points[b];
      s.spokes[a].push_back({std::atan2(q.y - p.y, q.x - p.x), b, seg});
      s.spokes[b].push_back({std::atan2(p.y - q.y, p.x - q.x), a, seg});
    }
  }
  number_hull_edges(m, first_hull_number(m), s);
  for (VertexId v{0}; v < m.vertex_count(); ++v) {
    auto& list = s.spokes[v];
    std::sort(list.begin(), list.end(), [](const Spoke& x, const Spoke& y) { return x.direction < y.direction; });
    for (const Spoke& k : list)
      if (std::find(s.segments[v].begin(), s.segments[v].end(), k.segment) == s.segments[v].end())
        s.segments[v].push_back(k.segment);
    if (s.segments[v].size() < 2) continue;
    for (std::uint32_t seg : s.segments[v]) {
      if (seg == kNone) continue;
      if (seg >= s.junctions.size()) s.junctions.resize(seg + 1);
      s.junctions[seg].push_back(v);
    }
  }
  return s;
}

// A vertex deltri made where input segments cross or overlap: not an input vertex, yet on two.
bool repaired_vertex(const Mesh& m, const SegmentVertices& s, VertexId v) {
  return m.kind[v] != VertexKind::Input && s.segments[v].size() >= 2;
}

double angle_between(double from, double to) {  // counter-clockwise, in [0, 2 pi)
  double a = to - from;
  while (a < 0) a += 2 * std::numbers::pi;
  while (a >= 2 * std::numbers::pi) a -= 2 * std::numbers::pi;
  return a;
}

// Rule 1: corner v of a triangle whose other corners q, r lie inside the sector between two
// neighbouring segments at v, when that sector is under kSmallInputAngle.
bool in_small_sector(const Mesh& m, const SegmentVertices& s, VertexId v, VertexId q, VertexId r) {
  const auto& list = s.spokes[v];
  if (list.size() < 2) return false;
  const Point& o = m.points[v];
  const double dq = std::atan2(m.points[q].y - o.y, m.points[q].x - o.x);
  const double dr = std::atan2(m.points[r].y - o.y, m.points[r].x - o.x);
  const double small = kSmallInputAngle * std::numbers::pi / 180.0;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const double from = list[i].direction, to = list[(i + 1) % list.size()].direction;
    const double gap = angle_between(from, to);
    if (gap >= small || gap == 0.0) continue;
    if (angle_between(from, dq) <= gap && angle_between(from, dr) <= gap) return true;
  }
  return false;
}

// The smallest angle at junction j between a piece of segment a and a piece of segment b. Each
// segment has at most two pieces at j, picked out in one pass: a vertex where hundreds of segments
// meet (spokes from a centre) is asked this for every miss near it.
double junction_angle(const SegmentVertices& s, VertexId j, std::uint32_t a, std::uint32_t b) {
  double along_a[2], along_b[2];
  int na = 0, nb = 0;
  for (const Spoke& x : s.spokes[j]) {
    if (x.segment == a && na < 2) along_a[na++] = x.direction;
    if (x.segment == b && nb < 2) along_b[nb++] = x.direction;
  }
  double smallest = std::numbers::pi;
  for (int i = 0; i < na; ++i)
    for (int k = 0; k < nb; ++k) {
      const double d = angle_between(along_a[i], along_b[k]);
      smallest = std::min({smallest, d, 2 * std::numbers::pi - d});
    }
  return smallest;
}

// Rules 2 and 3 for the edge p-q: the junction they explain the triangle by, or kNone. An edge
// with an end at the junction spans no wedge: it lies along one of the two segments, and its
// triangle is inside their small angle (rule 1 at that end) or outside it, unexplained.
VertexId junction_of_edge(const Mesh& m, const SegmentVertices& s, VertexId p, VertexId q, bool edge_on_segment) {
  const double small = kSmallInputAngle * std::numbers::pi / 180.0;
  for (std::uint32_t a : s.segments[p])
    for (std::uint32_t b : s.segments[q]) {
      if (a == b || a == kNone || b == kNone || a >= s.junctions.size()) continue;
      for (VertexId j : s.junctions[a]) {
        if (j == p || j == q) continue;
        if (std::find(s.segments[j].begin(), s.segments[j].end(), b) == s.segments[j].end()) continue;
        if (junction_angle(s, j, a, b) < small) return j;                     // rule 2: the wedge
        const double dp = length(m.points[p], m.points[j]), dq = length(m.points[q], m.points[j]);
        if (!edge_on_segment && std::fabs(dp - dq) <= 0.01 * std::max(dp, dq)) return j;  // rule 3: a shell
      }
    }
  return kNone;
}

// The vertex whose input angle explains t's miss, or kNone.
VertexId explaining_junction(const Mesh& m, const SegmentVertices& s, TriangleId t) {
  const VertexId* c = m.corners_at(t);
  for (int i = 0; i < 3; ++i)
    if (in_small_sector(m, s, c[i], c[(i + 1) % 3], c[(i + 2) % 3])) return c[i];
  double shortest = INFINITY;
  for (int i = 0; i < 3; ++i) shortest = std::min(shortest, length(m.points[c[i]], m.points[c[(i + 1) % 3]]));
  for (int i = 0; i < 3; ++i) {
    const VertexId p = c[i], q = c[(i + 1) % 3];
    if (length(m.points[p], m.points[q]) > shortest) continue;
    const bool on_segment = m.has_subsegments() && m.subseg.has(edge_of(t, i));
    const VertexId j = junction_of_edge(m, s, p, q, on_segment);
    if (j != kNone) return j;
  }
  return kNone;
}

// What a triangle misses, in its entry of the first pass's `missing`.
constexpr char kMissesAngle = 1, kMissesSize = 2;

// Slots from which the first pass takes two threads, as the Terminator's closing survey does.
constexpr std::uint32_t kParallelSlots = 100000;
// The corners come in slot order, their points from anywhere: fetched this many slots ahead.
constexpr std::uint32_t kPrefetchSlots = 16;

// The first pass over slots [from, to): the three first counts into `out` (which starts at zero),
// missing[t] set to what each triangle misses (kMissesAngle, kMissesSize). Each corner's points are
// loaded once for both tests.
void mark_misses(const Mesh& m, const BoundRequest& r, const AngleTest& test, TriangleId from, TriangleId to,
                 std::vector<char>& missing, BoundMisses& out) {
  for (TriangleId t = from; t < to; ++t) {
    if (const TriangleId ahead{t + kPrefetchSlots}; ahead < to && m.is_live(ahead))
      for (unsigned i = 0; i < 3; ++i) prefetch(&m.points[m.corner[edge_of(ahead, i)]]);
    if (!m.is_live(t)) continue;
    const auto [a, b, c] = m.corner_points(t);
    const bool angle = misses_angle(a, b, c, test), size = misses_size(m, t, a, b, c, r);
    out.below_angle += angle;
    out.above_size += size;
    missing[t] = static_cast<char>((angle ? kMissesAngle : 0) | (size ? kMissesSize : 0));
    out.total += missing[t] != 0;
  }
}

// The first pass, in two halves at once when asked for and worth it: the counts are sums, so the
// halves' add up to what one pass finds, whatever the thread count.
BoundMisses first_pass(const Mesh& m, const BoundRequest& r, const AngleTest& test, std::vector<char>& missing) {
  const TriangleId slots{m.triangle_slots()};
  BoundMisses half[2];
  run_halves(r.threads >= 2 && slots >= kParallelSlots, TriangleId{0}, slots,
             [&](TriangleId from, TriangleId to, int h) {
               BoundMisses mine;  // counted on each thread's own stack, not side by side
               mark_misses(m, r, test, from, to, missing, mine);
               half[h] = mine;
             });
  half[0].below_angle += half[1].below_angle;
  half[0].above_size += half[1].above_size;
  half[0].total += half[1].total;
  return half[0];
}

}  // namespace

BoundMisses count_bound_misses(const Mesh& m, const BoundRequest& r) {
  const AngleTest angle_test(r.angle.degrees());
  std::vector<char> missing(m.triangle_slots(), 0);
  BoundMisses out = first_pass(m, r, angle_test, missing);
  if (out.total == 0) return out;
  const SegmentVertices s = collect_spokes(m);
  for (TriangleId t{0}; t < m.triangle_slots(); ++t) {
    if (!m.is_live(t) || !missing[t]) continue;
    // The input explains a small angle, never a size: a triangle too large is not forced by it.
    const VertexId j = missing[t] == kMissesAngle ? explaining_junction(m, s, t) : kNone;
    bool touches_repair = false, touches_segment = false;
    for (int i = 0; i < 3; ++i) {
      const VertexId v = m.corner[edge_of(t, i)];
      touches_repair = touches_repair || repaired_vertex(m, s, v);
      touches_segment = touches_segment || !s.spokes[v].empty();
    }
    if (j != kNone && m.kind[j] == VertexKind::Input) ++out.small_input_angle;
    else if (j != kNone || touches_repair) ++out.repaired_input;
    else if (at_precision_limit(m, t)) ++out.double_precision;
    else if (r.steiner_limited || (r.segments_kept_whole && touches_segment)) ++out.steiner_limits;
    else ++out.other;
  }
  return out;
}

}  // namespace deltri
