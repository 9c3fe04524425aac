#include "quality/bound_misses.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <numbers>
#include <vector>

#include "refine/criteria.h"
#include "util/prefetch.h"
#include "util/run_both.h"

namespace deltri {
namespace {

// Input angles under this are "small": the region near them is exempt (as in Triangle and in
// Miller, Pav and Walkington's analysis, refinement cannot be asked to do better there).
constexpr double kSmallInputAngle = 60.0;

double length(const Point& a, const Point& b) { return std::hypot(b.x - a.x, b.y - a.y); }

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
constexpr char kMissesAngle = 1, kMissesSize = 2, kMissesMaxAngle = 4;

// The corner of t whose angle is above --max-angle between two subsegments (the input's angle
// there is larger still, and refinement leaves it: refine/criteria.h), or kNone.
VertexId large_angle_corner(const Mesh& m, TriangleId t, const BoundCheck& test) {
  const auto [a, b, c] = m.corner_points(t);
  const int k = test.above_max_angle(a, b, c);
  if (k < 0 || !angle_between_subsegments(m, edge_of(t, (static_cast<unsigned>(k) + 1) % 3))) return kNone;
  return m.corner[edge_of(t, static_cast<unsigned>(k))];
}

// The vertex whose input angles explain every angle t misses, or kNone: a size miss is never
// explained. With both a small and a large angle, the one made by deltri (a repair) if either is.
VertexId explaining_vertex(const Mesh& m, const SegmentVertices& s, TriangleId t, char missing, const BoundCheck& test) {
  if (missing & kMissesSize) return kNone;
  const VertexId small = (missing & kMissesAngle) ? explaining_junction(m, s, t) : kNone;
  if (!(missing & kMissesMaxAngle)) return small;
  const VertexId large = large_angle_corner(m, t, test);
  if (!(missing & kMissesAngle) || large == kNone) return large;
  if (small == kNone) return kNone;
  return m.kind[small] == VertexKind::Input ? large : small;
}

// Slots from which the first pass takes two threads, as the Terminator's closing survey does.
constexpr std::uint32_t kParallelSlots = 100000;
// The corners come in slot order, their points from anywhere: fetched this many slots ahead.
constexpr std::uint32_t kPrefetchSlots = 16;

// The first pass over slots [from, to): the three first counts into `out` (which starts at zero),
// missing[t] set to what each triangle misses (kMissesAngle, kMissesSize). Each corner's points are
// loaded once for both tests.
void mark_misses(const Mesh& m, const BoundCheck& test, TriangleId from, TriangleId to, std::vector<char>& missing,
                 BoundMisses& out) {
  for (TriangleId t = from; t < to; ++t) {
    if (const TriangleId ahead{t + kPrefetchSlots}; ahead < to && m.is_live(ahead))
      for (unsigned i = 0; i < 3; ++i) prefetch(&m.points[m.corner[edge_of(ahead, i)]]);
    if (!m.is_live(t)) continue;
    const auto [a, b, c] = m.corner_points(t);
    const bool angle = test.misses_angle(a, b, c), size = test.misses_size(m, t, a, b, c);
    const bool obtuse = test.above_max_angle(a, b, c) >= 0;
    out.below_angle += angle;
    out.above_size += size;
    out.above_max_angle += obtuse;
    missing[t] = static_cast<char>((angle ? kMissesAngle : 0) | (size ? kMissesSize : 0) | (obtuse ? kMissesMaxAngle : 0));
    out.total += missing[t] != 0;
  }
}

// The first pass, in two halves at once when asked for and worth it: the counts are sums, so the
// halves' add up to what one pass finds, whatever the thread count.
BoundMisses first_pass(const Mesh& m, const BoundRequest& r, const BoundCheck& test, std::vector<char>& missing) {
  const TriangleId slots{m.triangle_slots()};
  BoundMisses half[2];
  run_halves(r.threads >= 2 && slots >= kParallelSlots, TriangleId{0}, slots,
             [&](TriangleId from, TriangleId to, int h) {
               BoundMisses mine;  // counted on each thread's own stack, not side by side
               mark_misses(m, test, from, to, missing, mine);
               half[h] = mine;
             });
  half[0].below_angle += half[1].below_angle;
  half[0].above_size += half[1].above_size;
  half[0].above_max_angle += half[1].above_max_angle;
  half[0].total += half[1].total;
  return half[0];
}

}  // namespace

BoundMisses count_bound_misses(const Mesh& m, const BoundRequest& r) {
  const BoundCheck test(r.angle, r.size, r.max_angle);
  std::vector<char> missing(m.triangle_slots(), 0);
  BoundMisses out = first_pass(m, r, test, missing);
  if (out.total == 0) return out;
  const SegmentVertices s = collect_spokes(m);
  for (TriangleId t{0}; t < m.triangle_slots(); ++t) {
    if (!m.is_live(t) || !missing[t]) continue;
    const VertexId j = explaining_vertex(m, s, t, missing[t], test);
    bool touches_repair = false, touches_segment = false;
    for (int i = 0; i < 3; ++i) {
      const VertexId v = m.corner[edge_of(t, i)];
      touches_repair = touches_repair || repaired_vertex(m, s, v);
      touches_segment = touches_segment || !s.spokes[v].empty();
    }
    if (j != kNone && m.kind[j] == VertexKind::Input) ++((missing[t] & kMissesAngle) ? out.small_input_angle : out.large_input_angle);
    else if (j != kNone || touches_repair) ++out.repaired_input;
    else if (at_precision_limit(m, t)) ++out.double_precision;
    else if (r.steiner_limited || (r.segments_kept_whole && touches_segment)) ++out.steiner_limits;
    else ++out.other;
  }
  return out;
}

}  // namespace deltri
