// Segment coverage: every input segment (minus zero-length ones) must be a chain of mesh edges
// where it runs through the meshed domain; the parts outside it must meet no triangle.
//
// Tolerance (the only inexact decision in the checker): a vertex deltri created where two input
// segments cross is the intersection rounded to doubles, so it is usually not exactly on either
// segment. For a segment that properly crosses another input segment, a mesh vertex that is not an
// input vertex also counts as "on" the segment when its distance from the segment's line is at most
// kCrossUlps units in the last place of the largest coordinate involved (computed in long double).
// A correctly rounded intersection is within 0.71 ulp; 8 leaves room for a few roundings.
// With --refined the same tolerance holds for every segment: a refined mesh splits segments at
// rounded points (and a mesh refined twice, -r, splits pieces whose ends were already rounded).
// An input vertex counts as on a segment, besides exactly, when deltri's snapping rule (issue 17,
// docs/manual.md "Repaired PSLG input") takes it there: its distance from the segment's line is at
// most kSnapUlps ulps of the largest x and of the largest y of the three points, each weighted by
// the normal's component (a decimal T-junction one rounding off the segment). With --exact-input
// deltri does not snap, and its exact edge along the segment is then found first. With --refined or
// a crossing, a vertex that is not an input vertex also counts within kSnapUlps + 1 of that measure:
// refinement splits the pieces of a segment bent through a snapped vertex at rounded points.
// Every other decision (collinear vertices, whether a gap between two vertices on the segment
// meets a triangle) is exact.
// Where two segments' chains lie within the tolerance of each other (vertices a few ulps apart),
// more than one chain of edges passes for a segment. The walk then prefers, at each step, an edge
// the output .poly lists as a subsegment: the chain it follows must pass the same tolerance test,
// so the listing only chooses among valid chains, and the edges it marks as constrained are the
// ones the mesh was constrained by (marking another chain's edges would take a listed subsegment
// for an edge that must be locally Delaunay).
#include <algorithm>
#include <cmath>
#include <unordered_set>
#include <utility>
#include <vector>

#include "verify.h"

namespace mv {
namespace {

constexpr double kCrossUlps = 8.0;
constexpr double kSnapUlps = 4.01;  // deltri's 4, decided there exactly, here in long double

bool boxes_meet(const Point& a, const Point& b, const Point& c, const Point& d) {
  return std::max(a.x, b.x) >= std::min(c.x, d.x) && std::max(c.x, d.x) >= std::min(a.x, b.x) &&
         std::max(a.y, b.y) >= std::min(c.y, d.y) && std::max(c.y, d.y) >= std::min(a.y, b.y);
}

// Which input segments properly cross another one (interiors meet in a single point).
std::vector<char> crossing_segments(Context& c) {
  const auto& segs = c.in.segments;
  const auto& p = c.in.points;
  std::vector<char> crosses(segs.size(), 0);
  for (std::size_t i = 0; i < segs.size(); ++i)
    for (std::size_t j = i + 1; j < segs.size(); ++j) {
      const Point &a = p[segs[i].a], &b = p[segs[i].b], &d = p[segs[j].a], &e = p[segs[j].b];
      if (boxes_meet(a, b, d, e) && properly_cross(c.pred, a, b, d, e)) crosses[i] = crosses[j] = 1;
    }
  return crosses;
}

double ulp(double m) { return std::nextafter(m, INFINITY) - m; }

class SegmentWalk {
 public:
  SegmentWalk(Context& c, const PointIndex& input, const std::unordered_set<std::uint64_t>& listed, int segment,
              bool crosses)
      : c_(c),
        input_(input),
        listed_(listed),
        segment_(segment),
        a_(c.in.points[c.in.segments[segment].a]),
        b_(c.in.points[c.in.segments[segment].b]),
        crosses_(crosses),
        t_end_(param(b_)) {}

  // Marks the covering mesh edges; returns the point where coverage fails, if it does.
  // A search with backtracking, not a greedy walk: near a cluster of vertices a few ulps apart,
  // mesh vertices that are no part of the chain lie within the tolerance too (kCrossUlps), and the
  // nearest of them along the segment can be a dead end. Whether b can be reached from a vertex
  // depends on the vertex alone (the parameter only grows), so each dead end is tried once.
  std::optional<Point> walk() {
    std::vector<Step> path{{vertex_at(a_), a_, 0, {}, 0, false}};
    path.back().next = candidates(path.back());
    std::unordered_set<int> dead;
    Point stuck = a_;
    long double t_stuck = -1;
    while (!path.empty() && !(path.back().pos == b_)) {
      Step& top = path.back();
      if (top.t_pos > t_stuck) stuck = top.pos, t_stuck = top.t_pos;
      if (top.tried < top.next.size()) {
        const int w = top.next[top.tried++];
        if (dead.count(w)) continue;
        Step step{w, c_.out.points[w], param(c_.out.points[w]), {}, 0, false};
        step.next = candidates(step);
        path.push_back(std::move(step));
        continue;
      }
      const bool gap_tried = top.gap_tried;
      top.gap_tried = true;
      if (!gap_tried && top.next.empty()) {
        if (auto step = gap_from(top)) {
          step->next = candidates(*step);
          path.push_back(std::move(*step));
          continue;
        }
      }
      if (top.cur >= 0) dead.insert(top.cur);
      path.pop_back();
    }
    if (path.empty()) return stuck;
    for (std::size_t i = 0; i < path.size(); ++i) {
      note(path[i].cur);
      if (i > 0 && !path[i].by_gap) c_.segment_edges.insert(undirected_key(path[i - 1].cur, path[i].cur));
    }
    return std::nullopt;
  }

  // p lies on the segment between its ends, exactly or within the walk's tolerance.
  bool along(const Point& p) {
    const long double t = param(p);
    return t >= 0 && t <= t_end_ && on_segment(p);
  }
  int segment() const { return segment_; }

 private:
  struct Step {
    int cur;  // the mesh vertex at pos, or -1
    Point pos;
    long double t_pos;
    std::vector<int> next;  // neighbours that continue the segment: exactly on it first, then by t
    std::size_t tried;
    bool gap_tried;
    bool by_gap = false;  // reached across a stretch outside the mesh, not by an edge
  };

  // The neighbours of the step's vertex that continue the segment: those exactly on it (a rounded
  // vertex of a nearly collinear neighbour segment can be within the tolerance too, and must not
  // hide the exact edge), then those within the tolerance, each group nearest first; within each,
  // the edges the output lists as subsegments come first (see the header).
  std::vector<int> candidates(const Step& at) {
    std::vector<std::pair<long double, int>> groups[4];  // listed exact, listed close, exact, close
    if (at.cur >= 0)
      for (int w : c_.topo.adjacent[at.cur]) {
        const Point& q = c_.out.points[w];
        const long double t = param(q);
        if (!(t > at.t_pos && t <= t_end_)) continue;
        const int unlisted = listed_.count(undirected_key(at.cur, w)) ? 0 : 2;
        if (exactly_on(q)) groups[unlisted].push_back({t, w});
        else if (near(q)) groups[unlisted + 1].push_back({t, w});
      }
    std::vector<int> out;
    for (auto& group : groups) {
      std::sort(group.begin(), group.end());
      for (const auto& [t, w] : group) out.push_back(w);
    }
    return out;
  }

  // No mesh edge continues the segment: up to the next vertex on it, it must be outside the mesh.
  std::optional<Step> gap_from(const Step& at) {
    Point next = b_;
    long double t_next = t_end_;
    for (int v : c_.vertex_grid.query(lower(at.pos, b_), upper(at.pos, b_))) {
      const Point& q = c_.out.points[v];
      const long double t = param(q);
      if (t > at.t_pos && t < t_next && on_segment(q)) {
        next = q;
        t_next = t;
      }
    }
    if (c_.open_segment_meets_mesh(at.pos, next)) return std::nullopt;
    return Step{vertex_at(next), next, t_next, {}, 0, false, true};
  }

  static Point lower(const Point& a, const Point& b) { return {std::min(a.x, b.x), std::min(a.y, b.y)}; }
  static Point upper(const Point& a, const Point& b) { return {std::max(a.x, b.x), std::max(a.y, b.y)}; }

  long double param(const Point& p) const {
    return (static_cast<long double>(p.x) - a_.x) * (static_cast<long double>(b_.x) - a_.x) +
           (static_cast<long double>(p.y) - a_.y) * (static_cast<long double>(b_.y) - a_.y);
  }
  void note(int v) {
    if (v >= 0) c_.segments_at[v].push_back(segment_);
  }
  int vertex_at(const Point& p) const {
    const auto it = c_.topo.used_at.find(p);
    return it == c_.topo.used_at.end() ? -1 : it->second;
  }
  bool exactly_on(const Point& p) { return on_closed_segment(c_.pred, a_, b_, p); }
  bool snapped(const Point& p, long double ulps) const {
    const long double dx = static_cast<long double>(b_.x) - a_.x, dy = static_cast<long double>(b_.y) - a_.y;
    const long double cross = dx * (static_cast<long double>(p.y) - a_.y) - dy * (static_cast<long double>(p.x) - a_.x);
    const long double ux = 0x1p-52L * std::max({std::fabs(a_.x), std::fabs(b_.x), std::fabs(p.x)});
    const long double uy = 0x1p-52L * std::max({std::fabs(a_.y), std::fabs(b_.y), std::fabs(p.y)});
    return std::fabs(cross) <= ulps * (std::fabs(dy) * std::max(ux, 0x1p-1074L) + std::fabs(dx) * std::max(uy, 0x1p-1074L));
  }
  bool near(const Point& p) const {
    if (input_.count(p)) return snapped(p, kSnapUlps);
    if (!crosses_) return false;
    // Where snapping bent the segment through an input vertex (up to kSnapUlps off it), a refined
    // mesh splits the bent pieces at points rounded on them: within that bound and an ulp more.
    if (snapped(p, kSnapUlps + 1)) return true;
    const long double dx = static_cast<long double>(b_.x) - a_.x, dy = static_cast<long double>(b_.y) - a_.y;
    const long double cross = dx * (static_cast<long double>(p.y) - a_.y) - dy * (static_cast<long double>(p.x) - a_.x);
    const double m = std::max({std::fabs(a_.x), std::fabs(a_.y), std::fabs(b_.x), std::fabs(b_.y), std::fabs(p.x), std::fabs(p.y)});
    return std::fabs(cross) <= kCrossUlps * ulp(m) * std::sqrt(dx * dx + dy * dy);
  }
  bool on_segment(const Point& p) { return exactly_on(p) || near(p); }

  Context& c_;
  const PointIndex& input_;
  const std::unordered_set<std::uint64_t>& listed_;  // the output .poly's subsegments
  int segment_;
  Point a_, b_;
  bool crosses_;
  long double t_end_;
};

// A segment's walk finds one chain; where two segments' chains lie within the tolerance of each
// other, the mesh's own chain for the segment can be another. Every output subsegment that runs
// along an input segment (both ends on it, exactly or within the tolerance, from a vertex already
// found on it) is a constrained edge of the mesh as well: followed from the vertices the walks
// found, chain by chain.
void mark_listed_chains(Context& c, std::vector<SegmentWalk>& walks) {
  if (!c.out.poly_segments) return;
  std::vector<std::vector<int>> listed_at(c.out.points.size());
  for (const EdgeLine& e : *c.out.poly_segments) {
    listed_at[e.a].push_back(e.b);
    listed_at[e.b].push_back(e.a);
  }
  std::vector<int> walk_of(c.in.segments.size(), -1);
  for (std::size_t k = 0; k < walks.size(); ++k) walk_of[walks[k].segment()] = static_cast<int>(k);
  std::vector<std::pair<int, int>> work;  // (vertex, walk)
  std::unordered_set<std::uint64_t> seen;   // edge_key(vertex, walk)
  for (std::size_t v = 0; v < c.segments_at.size(); ++v)
    for (int s : c.segments_at[v])
      if (seen.insert(edge_key(static_cast<int>(v), walk_of[s])).second) work.push_back({static_cast<int>(v), walk_of[s]});
  while (!work.empty()) {
    const auto [v, k] = work.back();
    work.pop_back();
    for (int w : listed_at[v])
      if (walks[k].along(c.out.points[w])) {
        c.segment_edges.insert(undirected_key(v, w));
        if (seen.insert(edge_key(w, k)).second) {
          c.segments_at[w].push_back(walks[k].segment());
          work.push_back({w, k});
        }
      }
  }
}

}  // namespace

void check_segments(Context& c, Failures& f) {
  PointIndex input;
  for (std::size_t v = 0; v < c.in.points.size(); ++v) input.emplace(c.in.points[v], static_cast<int>(v));
  const std::vector<char> crosses = crossing_segments(c);
  std::unordered_set<std::uint64_t> listed;
  if (c.out.poly_segments)
    for (const EdgeLine& e : *c.out.poly_segments) listed.insert(undirected_key(e.a, e.b));
  c.segments_at.assign(c.out.points.size(), {});
  std::vector<SegmentWalk> walks;
  for (std::size_t s = 0; s < c.in.segments.size(); ++s) {
    const Point a = c.in.points[c.in.segments[s].a], b = c.in.points[c.in.segments[s].b];
    if (a == b) continue;  // zero-length: deltri ignores it
    walks.emplace_back(c, input, listed, static_cast<int>(s), crosses[s] || c.refined);
    if (const auto stuck = walks.back().walk())
      f.add("segments", "input segment " + std::to_string(s) + " " + fmt(a) + "-" + fmt(b) +
                            " is not a chain of mesh edges after " + fmt(*stuck));
  }
  mark_listed_chains(c, walks);
}

}  // namespace mv
