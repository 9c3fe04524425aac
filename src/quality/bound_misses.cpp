#include "quality/bound_misses.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <numbers>
#include <span>
#include <vector>

#include "geometry/constructions.h"
#include "refine/criteria.h"
#include "util/prefetch.h"
#include "util/run_both.h"

namespace deltri {
namespace {

// Input angles under this are "small": the region near them is exempt (as in Triangle and in
// Miller, Pav and Walkington's analysis, refinement cannot be asked to do better there).
constexpr double kSmallInputAngle = 60.0;

double length(const Point& a, const Point& b) { return std::hypot(b.x - a.x, b.y - a.y); }

// The reports' relative margin (BoundCheck): a triangle at a floor but for rounding meets it.
constexpr double kMargin = 1e-12;

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

// A list per key, all in one array: vectors of vectors, an allocation and a free for each of a
// few hundred thousand vertices, were most of this check's cost.
template <class T>
struct Rows {
  std::vector<std::uint32_t> start{0};  // row k is items[start[k], start[k + 1])
  std::vector<T> items;
  std::size_t size() const { return start.size() - 1; }
  std::span<T> operator[](std::size_t k) { return {items.data() + start[k], items.data() + start[k + 1]}; }
  std::span<const T> operator[](std::size_t k) const { return {items.data() + start[k], items.data() + start[k + 1]}; }
  // Rows 0 .. counts.size() - 1, row k with room for counts[k] items.
  void size_rows(const std::vector<std::uint32_t>& counts) {
    start.assign(counts.size() + 1, 0);
    for (std::size_t k = 0; k < counts.size(); ++k) start[k + 1] = start[k] + counts[k];
    items.resize(start.back());
  }
};

struct SegmentVertices {
  Rows<Spoke> spokes;             // per vertex, by direction
  Rows<std::uint32_t> segments;   // per vertex: the input segments it lies on, in the spokes' order
  Rows<VertexId> junctions;       // per input segment: its vertices on other segments too
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
  for (Spoke& k : s.spokes.items)
    if (k.segment != kNone && k.segment >= first) k.segment = first + root_of(parent, k.segment - first);
}

// The subsegments, each once (from its edge with the smaller id), in slot order: their ends and
// input segment numbers.
struct SpokePair {
  VertexId a, b;
  std::uint32_t segment;
};

std::vector<SpokePair> subsegment_list(const Mesh& m) {
  std::vector<SpokePair> out;
  for (TriangleId t{0}; t < m.triangle_slots(); ++t) {
    if (!m.is_live(t)) continue;
    for (EdgeRef e : edges_of(t)) {
      if (!m.subseg.has(e) || (m.link[e] != kNone && m.link[e] < e)) continue;
      out.push_back({m.org(e), m.dest(e), m.subsegments[m.subseg[e]].segment});
    }
  }
  return out;
}

// Each vertex's spokes in the order of the subsegment list (the order the sort by direction
// starts from).
void fill_spokes(const Mesh& m, const std::vector<SpokePair>& list, Rows<Spoke>& spokes) {
  std::vector<std::uint32_t> count(m.vertex_count(), 0);
  for (const SpokePair& k : list) ++count[k.a], ++count[k.b];
  spokes.size_rows(count);
  std::fill(count.begin(), count.end(), 0);
  for (const SpokePair& k : list) {
    const Point &p = m.points[k.a], &q = m.points[k.b];
    spokes.items[spokes.start[k.a] + count[k.a]++] = {std::atan2(q.y - p.y, q.x - p.x), k.b, k.segment};
    spokes.items[spokes.start[k.b] + count[k.b]++] = {std::atan2(p.y - q.y, p.x - q.x), k.a, k.segment};
  }
}

// Each vertex's input segments (the distinct numbers of its spokes, in their order) and each
// segment's junctions (its vertices on two or more), the vertices in increasing order.
void list_segments(const Mesh& m, SegmentVertices& s) {
  std::vector<std::uint32_t> junction_count;
  s.segments.start.assign(m.vertex_count() + 1, 0);
  for (VertexId v{0}; v < m.vertex_count(); ++v) {
    for (const Spoke& k : s.spokes[v]) {
      const auto mine = s.segments.items.begin() + s.segments.start[v];
      if (std::find(mine, s.segments.items.end(), k.segment) == s.segments.items.end())
        s.segments.items.push_back(k.segment);
    }
    s.segments.start[v + 1] = static_cast<std::uint32_t>(s.segments.items.size());
    if (s.segments[v].size() < 2) continue;
    for (std::uint32_t seg : s.segments[v])
      if (seg != kNone) {
        if (seg >= junction_count.size()) junction_count.resize(seg + 1, 0);
        ++junction_count[seg];
      }
  }
  s.junctions.size_rows(junction_count);
  std::fill(junction_count.begin(), junction_count.end(), 0);
  for (VertexId v{0}; v < m.vertex_count(); ++v)
    if (s.segments[v].size() >= 2)
      for (std::uint32_t seg : s.segments[v])
        if (seg != kNone) s.junctions.items[s.junctions.start[seg] + junction_count[seg]++] = v;
}

SegmentVertices collect_spokes(const Mesh& m) {
  SegmentVertices s;
  if (!m.has_subsegments()) {
    s.spokes.start.assign(m.vertex_count() + 1, 0);
    s.segments.start.assign(m.vertex_count() + 1, 0);
    return s;
  }
  fill_spokes(m, subsegment_list(m), s.spokes);
  number_hull_edges(m, first_hull_number(m), s);
  for (VertexId v{0}; v < m.vertex_count(); ++v) {
    const std::span<Spoke> list = s.spokes[v];
    std::sort(list.begin(), list.end(), [](const Spoke& x, const Spoke& y) { return x.direction < y.direction; });
  }
  list_segments(m, s);
  return s;
}

// A vertex deltri made where input segments cross or overlap: not an input vertex, yet on two.
bool repaired_vertex(const Mesh& m, const SegmentVertices& s, VertexId v) {
  return m.kind[v] != VertexKind::Input && s.segments[v].size() >= 2;
}

// A vertex whose angles between segments are the input's: an input vertex, or one deltri made where
// input segments cross (any mesh keeping the segments has a vertex at the crossing, and the angles
// the segments cross at are there whatever the mesh; tests/tools/verify_quality.cpp's junctions
// include crossings likewise).
bool input_angle_vertex(const Mesh& m, const SegmentVertices& s, VertexId v) {
  return m.kind[v] == VertexKind::Input || repaired_vertex(m, s, v);
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

// Theorem 12 of Shewchuk's paper (Sec. 6.3): where the smallest input angle of a subsegment cluster
// is phi <= 60 degrees, the Terminator leaves no triangle whose smallest angle is below
// arcsin(sin(phi / 2) / sqrt 2) (with diametral lenses the floor is higher, Sec. 6.4). A triangle
// below that floor is not what the input angle forces, whatever its place. Degrees; phi in radians.
double theorem12_floor_deg(double phi) {
  return std::asin(std::sin(phi / 2.0) / std::numbers::sqrt2) * (180.0 / std::numbers::pi);
}

double smallest_angle_deg(const Point& a, const Point& b, const Point& c) {
  return std::min({angle_degrees(a, b, c), angle_degrees(b, c, a), angle_degrees(c, a, b)});
}

// r lies in the closed triangle jpq (either orientation), by the signs of rounded cross products.
bool in_closed_triangle(const Point& j, const Point& p, const Point& q, const Point& r) {
  const auto cross = [](const Point& a, const Point& b, const Point& c) {
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
  };
  const double turn = cross(j, p, q);
  if (turn == 0.0) return false;
  const double side = turn > 0.0 ? 1.0 : -1.0;
  return side * cross(j, p, r) >= 0.0 && side * cross(p, q, r) >= 0.0 && side * cross(q, j, r) >= 0.0;
}

// Rule 2 for triangle pqr with shortest edge p-q: the junction j of two segments that meet there at
// under 60 degrees, p on one and q on the other (neither at j), with r in the corner triangle jpq
// (r may be j itself), or, where that angle is below the -q angle (bound_deg), with p and q at
// distances from j equal within 0.1%: the triangle lies in the shells the input angle cuts off.
// (Below the bound the Terminator spares every triangle on such a shell edge, as Triangle does:
// splitting the ones beyond it cut the shells down without end; Terminator::shell_exempt.) Its
// smallest angle must be at least the Theorem 12 floor of that angle. Else kNone. An edge with an
// end at the junction spans no wedge: it lies along one of the two segments, and its triangle is
// inside their small angle (rule 1 at that end) or outside it, unexplained.
VertexId corner_junction(const Mesh& m, const SegmentVertices& s, VertexId p, VertexId q, VertexId r, double smallest,
                         double bound_deg) {
  const double small = kSmallInputAngle * std::numbers::pi / 180.0;
  const double bound = bound_deg * std::numbers::pi / 180.0;
  for (std::uint32_t a : s.segments[p])
    for (std::uint32_t b : s.segments[q]) {
      if (a == b || a == kNone || b == kNone || a >= s.junctions.size()) continue;
      for (VertexId j : s.junctions[a]) {
        if (j == p || j == q) continue;
        if (std::find(s.segments[j].begin(), s.segments[j].end(), b) == s.segments[j].end()) continue;
        const double phi = junction_angle(s, j, a, b);
        if (phi >= small || smallest < theorem12_floor_deg(phi) * (1.0 - kMargin)) continue;
        if (r == j || in_closed_triangle(m.points[j], m.points[p], m.points[q], m.points[r])) return j;
        const double dp = length(m.points[p], m.points[j]), dq = length(m.points[q], m.points[j]);
        if (phi < bound && std::fabs(dp - dq) <= 0.001 * std::max(dp, dq)) return j;
      }
    }
  return kNone;
}

// Rule 3's subsegments: a mesh edge on a segment, from a vertex j where that segment bounds a sector
// under 60 degrees between neighbouring segments (the subsegment clusters of Sec. 6.3), with phi the
// smallest such sector it bounds. Its closed diametral disk, centre and squared radius.
struct ClusterDisk {
  VertexId junction;
  double phi;
  Point centre;
  double radius2;
};

// The disks, in a uniform grid of about one cell per disk for the lookups of the misses' circumcentres;
// a disk over more than kMaxCells cells goes on a list every lookup reads.
class ClusterDisks {
 public:
  ClusterDisks(const Mesh& m, const SegmentVertices& s) {
    const double small = kSmallInputAngle * std::numbers::pi / 180.0;
    for (VertexId j{0}; j < m.vertex_count(); ++j) {
      const auto& list = s.spokes[j];
      const std::size_t n = list.size();
      if (n < 2) continue;
      for (std::size_t i = 0; i < n; ++i) {
        const double before = angle_between(list[(i + n - 1) % n].direction, list[i].direction);
        const double after = angle_between(list[i].direction, list[(i + 1) % n].direction);
        double phi = HUGE_VAL;
        for (double gap : {before, after})
          if (gap > 0.0 && gap < small) phi = std::min(phi, gap);
        if (phi == HUGE_VAL) continue;
        const Point& a = m.points[j];
        const Point& b = m.points[list[i].to];
        const Point centre = midpoint(a, b);
        disks_.push_back({j, phi, centre, 0.25 * ((b.x - a.x) * (b.x - a.x) + (b.y - a.y) * (b.y - a.y))});
      }
    }
    if (disks_.empty()) return;
    lo_ = hi_ = disks_[0].centre;
    for (const ClusterDisk& d : disks_) {
      const double r = std::sqrt(d.radius2);
      lo_ = {std::min(lo_.x, d.centre.x - r), std::min(lo_.y, d.centre.y - r)};
      hi_ = {std::max(hi_.x, d.centre.x + r), std::max(hi_.y, d.centre.y + r)};
    }
    side_ = std::max<std::size_t>(1, static_cast<std::size_t>(std::sqrt(static_cast<double>(disks_.size()))));
    cells_.resize(side_ * side_);
    for (std::uint32_t k = 0; k < disks_.size(); ++k) {
      const double r = std::sqrt(disks_[k].radius2);
      const std::size_t x0 = cell(disks_[k].centre.x - r, lo_.x, hi_.x), x1 = cell(disks_[k].centre.x + r, lo_.x, hi_.x);
      const std::size_t y0 = cell(disks_[k].centre.y - r, lo_.y, hi_.y), y1 = cell(disks_[k].centre.y + r, lo_.y, hi_.y);
      if ((x1 - x0 + 1) * (y1 - y0 + 1) > kMaxCells) {
        large_.push_back(k);
        continue;
      }
      for (std::size_t y = y0; y <= y1; ++y)
        for (std::size_t x = x0; x <= x1; ++x) cells_[y * side_ + x].push_back(k);
    }
  }

  // The junction of a disk that holds p, whose Theorem 12 floor `smallest` meets, or kNone.
  VertexId holding(const Point& p, double smallest) const {
    if (disks_.empty() || !(p.x >= lo_.x && p.x <= hi_.x && p.y >= lo_.y && p.y <= hi_.y)) return find(large_, p, smallest);
    const VertexId j = find(cells_[cell(p.y, lo_.y, hi_.y) * side_ + cell(p.x, lo_.x, hi_.x)], p, smallest);
    return j != kNone ? j : find(large_, p, smallest);
  }

 private:
  static constexpr std::size_t kMaxCells = 64;
  std::size_t cell(double v, double lo, double hi) const {
    if (!(hi > lo)) return 0;
    const double f = (v - lo) / (hi - lo) * static_cast<double>(side_);
    return static_cast<std::size_t>(std::clamp(f, 0.0, static_cast<double>(side_ - 1)));
  }
  VertexId find(const std::vector<std::uint32_t>& list, const Point& p, double smallest) const {
    for (std::uint32_t k : list) {
      const ClusterDisk& d = disks_[k];
      const double dx = p.x - d.centre.x, dy = p.y - d.centre.y;
      if (dx * dx + dy * dy <= d.radius2 * (1.0 + kMargin) && smallest >= theorem12_floor_deg(d.phi) * (1.0 - kMargin))
        return d.junction;
    }
    return kNone;
  }
  std::vector<ClusterDisk> disks_;
  std::vector<std::vector<std::uint32_t>> cells_;
  std::vector<std::uint32_t> large_;
  Point lo_{}, hi_{};
  std::size_t side_ = 1;
};

// The circumcentre of abc, relative to a for accuracy; NaN coordinates for a degenerate triangle.
Point circumcentre_of(const Point& a, const Point& b, const Point& c) {
  const double bx = b.x - a.x, by = b.y - a.y, cx = c.x - a.x, cy = c.y - a.y;
  const double d = 2.0 * (bx * cy - by * cx);
  const double b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
  return {a.x + (cy * b2 - by * c2) / d, a.y + (bx * c2 - cx * b2) / d};
}

// The vertex whose input angle explains t's miss, or kNone.
VertexId explaining_junction(const Mesh& m, const SegmentVertices& s, const ClusterDisks& disks, TriangleId t,
                             double bound_deg) {
  const VertexId* c = m.corners_at(t);
  for (int i = 0; i < 3; ++i)
    if (in_small_sector(m, s, c[i], c[(i + 1) % 3], c[(i + 2) % 3])) return c[i];
  const Point &a = m.points[c[0]], &b = m.points[c[1]], &d = m.points[c[2]];
  const double smallest = smallest_angle_deg(a, b, d);
  double shortest = INFINITY;
  for (int i = 0; i < 3; ++i) shortest = std::min(shortest, length(m.points[c[i]], m.points[c[(i + 1) % 3]]));
  for (int i = 0; i < 3; ++i) {
    const VertexId p = c[i], q = c[(i + 1) % 3], r = c[(i + 2) % 3];
    if (length(m.points[p], m.points[q]) > shortest) continue;
    const VertexId j = corner_junction(m, s, p, q, r, smallest, bound_deg);
    if (j != kNone) return j;
  }
  return disks.holding(circumcentre_of(a, b, d), smallest);  // rule 3
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
// explained. An angle above --max-angle is explained by the larger input angle it lies in
// (large_angle_corner) or, failing that, as a small angle is (explaining_junction: next to an input
// angle under 60 degrees, where the Terminator declines or the guard refuses the splits that would
// remove it; docs/refinement.md, "Largest-angle bound"). With both a small and a large angle, both
// must be explained; the large one's vertex is returned. `by_large` says which explained it.
VertexId explaining_vertex(const Mesh& m, const SegmentVertices& s, const ClusterDisks& disks, TriangleId t, char missing,
                           const BoundCheck& test, double bound_deg, bool& by_large) {
  by_large = false;
  if (missing & kMissesSize) return kNone;
  const VertexId large = (missing & kMissesMaxAngle) ? large_angle_corner(m, t, test) : kNone;
  const bool small_needed = (missing & kMissesAngle) || large == kNone;
  const VertexId small = small_needed ? explaining_junction(m, s, disks, t, bound_deg) : kNone;
  if (large == kNone) return small;
  by_large = true;
  if (!(missing & kMissesAngle)) return large;
  return small == kNone ? kNone : large;
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
  const ClusterDisks disks(m, s);
  for (TriangleId t{0}; t < m.triangle_slots(); ++t) {
    if (!m.is_live(t) || !missing[t]) continue;
    bool by_large = false;
    const VertexId j = explaining_vertex(m, s, disks, t, missing[t], test, r.angle.degrees(), by_large);
    bool touches_repair = false, touches_segment = false;
    for (int i = 0; i < 3; ++i) {
      const VertexId v = m.corner[edge_of(t, i)];
      touches_repair = touches_repair || repaired_vertex(m, s, v);
      touches_segment = touches_segment || !s.spokes[v].empty();
    }
    if (j != kNone && input_angle_vertex(m, s, j)) {
      ++(by_large ? out.large_input_angle : out.small_input_angle);
      out.at_input_crossings += m.kind[j] != VertexKind::Input;
    } else if (j != kNone || touches_repair) {
      ++out.repaired_input;
    }
    else if (at_precision_limit(m, t)) ++out.double_precision;
    else if (r.steiner_limited || (r.segments_kept_whole && touches_segment)) ++out.steiner_limits;
    else ++out.other;
  }
  return out;
}

}  // namespace deltri
