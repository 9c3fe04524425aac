#include "mesh/embedding.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "geometry/box_pairs.h"

namespace deltri {
namespace {

// Lower: least x, then least y (the lowest vertex of a polygon is a convex corner of it).
bool lower(const Point& a, const Point& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); }

// For a, v, w on one line with a and w apart from v: w lies on a's side of v.
bool same_side(const Point& v, const Point& a, const Point& w) {
  return (a.x < v.x) == (w.x < v.x) && (a.x > v.x) == (w.x > v.x) && (a.y < v.y) == (w.y < v.y) &&
         (a.y > v.y) == (w.y > v.y);
}

class Certificate {
 public:
  Certificate(const Mesh& mesh, Predicates& pred) : mesh_(mesh), pred_(pred) {}

  bool run() { return collect_boundary() && trace_loops() && corners_turn() && no_edges_meet() && loops_nest(); }

 private:
  struct Loop {
    std::uint32_t lowest;  // the boundary edge ending at the loop's lowest vertex
    bool counter_clockwise = false;
  };

  const Point& org(std::uint32_t k) const { return mesh_.point(mesh_.org(boundary_[k])); }
  const Point& dest(std::uint32_t k) const { return mesh_.point(mesh_.dest(boundary_[k])); }
  // The work allowed to the parts that are not linear in the worst case; past it the certificate
  // gives up (it is meant to cost little next to the pair search, which then decides).
  std::size_t budget() const { return 16 * boundary_.size() + 4096; }

  // The edges without a twin, each vertex leaving at most one (two: a "bow tie", refused).
  bool collect_boundary() {
    leaving_.assign(mesh_.vertex_count(), kNone);
    for (EdgeRef e{0}; e < mesh_.corner.size(); ++e) {
      if (!mesh_.is_live(triangle_of(e)) || mesh_.link[e] != kNone) continue;
      if (leaving_[mesh_.org(e)] != kNone) return false;
      leaving_[mesh_.org(e)] = static_cast<std::uint32_t>(boundary_.size());
      boundary_.push_back(e);
    }
    return !boundary_.empty();  // triangles without a boundary cannot all be counter-clockwise
  }

  // next_[k]: the boundary edge after k; loop_[k]: k's loop. Twins pair each arrival at a vertex
  // with a departure, so a vertex left by one boundary edge is reached by one, and the loops close.
  bool trace_loops() {
    next_.resize(boundary_.size());
    for (std::uint32_t k = 0; k < boundary_.size(); ++k) next_[k] = leaving_[mesh_.dest(boundary_[k])];
    loop_.assign(boundary_.size(), kNone);
    for (std::uint32_t k = 0; k < boundary_.size(); ++k) {
      if (loop_[k] != kNone) continue;
      const auto id = static_cast<std::uint32_t>(loops_.size());
      loops_.push_back({k});
      std::uint32_t j = k;
      for (; j != kNone && loop_[j] == kNone; j = next_[j]) {
        loop_[j] = id;
        if (lower(dest(j), dest(loops_.back().lowest))) loops_.back().lowest = j;
      }
      if (j != k) return false;  // not a permutation: the twins were not as promised
    }
    return true;
  }

  // Consecutive boundary edges a->v, v->w meet only at v unless w lies along v->a.
  bool corners_turn() {
    for (std::uint32_t k = 0; k < boundary_.size(); ++k) {
      const Point &a = org(k), &v = dest(k), &w = dest(next_[k]);
      if (pred_.orient2d(a, v, w) == 0 && same_side(v, a, w)) return false;
    }
    return true;
  }

  // Boundary edges with no endpoint in common are disjoint (with one in common they follow each
  // other at it, as no vertex has two boundary edges leaving or reaching it).
  bool no_edges_meet() {
    std::vector<Box> boxes(boundary_.size());
    for (std::uint32_t k = 0; k < boundary_.size(); ++k) boxes[k].add(org(k)), boxes[k].add(dest(k));
    std::size_t tested = 0;
    bool gave_up = false;
    const bool met = BoxPairs(std::move(boxes)).any([&](std::uint32_t i, std::uint32_t j) {
      if (share_endpoint(i, j)) return false;
      gave_up = ++tested > budget();
      return gave_up || segments_meet(org(i), dest(i), org(j), dest(j));
    });
    return !met && !gave_up;
  }

  bool share_endpoint(std::uint32_t i, std::uint32_t j) const {
    const EdgeRef e = boundary_[i], f = boundary_[j];
    return mesh_.org(e) == mesh_.org(f) || mesh_.org(e) == mesh_.dest(f) || mesh_.dest(e) == mesh_.org(f) ||
           mesh_.dest(e) == mesh_.dest(f);
  }

  // Closed segments ab and cd meet: neither has both ends strictly on one side of the other's
  // line, and if all four are on one line, their boxes meet.
  bool segments_meet(const Point& a, const Point& b, const Point& c, const Point& d) {
    const double o1 = pred_.orient2d(a, b, c), o2 = pred_.orient2d(a, b, d);
    if ((o1 > 0 && o2 > 0) || (o1 < 0 && o2 < 0)) return false;
    const double o3 = pred_.orient2d(c, d, a), o4 = pred_.orient2d(c, d, b);
    if ((o3 > 0 && o4 > 0) || (o3 < 0 && o4 < 0)) return false;
    if (o1 != 0 || o2 != 0) return true;
    return std::max(std::min(a.x, b.x), std::min(c.x, d.x)) <= std::min(std::max(a.x, b.x), std::max(c.x, d.x)) &&
           std::max(std::min(a.y, b.y), std::min(c.y, d.y)) <= std::min(std::max(a.y, b.y), std::max(c.y, d.y));
  }

  // (W) of embedding.h: each loop's orientation at its lowest vertex, a convex corner that
  // corners_turn keeps from being flat; then the other loops' winding there.
  bool loops_nest() {
    for (Loop& l : loops_) {
      const double o = pred_.orient2d(org(l.lowest), dest(l.lowest), dest(next_[l.lowest]));
      if (o == 0) return false;
      l.counter_clockwise = o > 0;
    }
    if (loops_.size() == 1) return loops_[0].counter_clockwise;
    return make_strips() && windings_fit();
  }

  // Horizontal strips over the boundary, each listing the edges whose height range meets it, so
  // that a ray from a point crosses only edges listed in the point's strip.
  bool make_strips() {
    double lo = dest(0).y, hi = lo;
    for (std::uint32_t k = 0; k < boundary_.size(); ++k) lo = std::min(lo, dest(k).y), hi = std::max(hi, dest(k).y);
    strips_ = strip_count(static_cast<long double>(hi) - lo);
    y0_ = lo;
    const long double h = (static_cast<long double>(hi) - lo) / strips_;
    strip_h_ = h > 0 ? h : 1;
    strip_start_.assign(strips_ + 1, 0);
    std::size_t entries = 0;
    for (std::uint32_t k = 0; k < boundary_.size(); ++k) {
      const auto [r0, r1] = strip_range(k);
      for (std::uint32_t r = r0; r <= r1; ++r) ++strip_start_[r + 1];
      if ((entries += r1 - r0 + 1) > budget()) return false;
    }
    for (std::uint32_t r = 0; r < strips_; ++r) strip_start_[r + 1] += strip_start_[r];
    in_strip_.resize(entries);
    std::vector<std::size_t> next(strip_start_.begin(), strip_start_.end() - 1);
    for (std::uint32_t k = 0; k < boundary_.size(); ++k) {
      const auto [r0, r1] = strip_range(k);
      for (std::uint32_t r = r0; r <= r1; ++r) in_strip_[next[r]++] = k;
    }
    return true;
  }

  // As many strips as boundary edges, but no thinner than the edges are high on average, so that
  // an edge is listed in about two strips (circular holes of 64 edges in rows: about 2,000 strips
  // for 130,000 edges, not one per edge with each listed in dozens).
  std::uint32_t strip_count(long double span) const {
    long double heights = 0;
    for (std::uint32_t k = 0; k < boundary_.size(); ++k) heights += std::fabs(static_cast<long double>(dest(k).y) - org(k).y);
    const long double edges = static_cast<long double>(boundary_.size());
    const long double wanted = heights > 0 ? edges * span / heights : 1.0L;
    return static_cast<std::uint32_t>(std::clamp(wanted, 1.0L, edges));
  }

  std::pair<std::uint32_t, std::uint32_t> strip_range(std::uint32_t k) const {
    const double a = org(k).y, b = dest(k).y;
    return {strip(std::min(a, b)), strip(std::max(a, b))};
  }
  std::uint32_t strip(double y) const { return grid_index(y, y0_, strip_h_, strips_); }

  bool windings_fit() {
    std::size_t scanned = 0;
    for (std::uint32_t id = 0; id < loops_.size(); ++id) {
      const Point& q = dest(loops_[id].lowest);
      const std::uint32_t r = strip(q.y);
      if ((scanned += strip_start_[r + 1] - strip_start_[r]) > budget()) return false;
      int winding = 0;
      for (std::size_t i = strip_start_[r]; i < strip_start_[r + 1]; ++i)
        if (loop_[in_strip_[i]] != id) winding += crossing(in_strip_[i], q);
      if (winding != (loops_[id].counter_clockwise ? 0 : 1)) return false;
    }
    return true;
  }

  // Edge k's signed crossing of the ray from q towards +x, which meets no boundary edge at q
  // itself (no_edges_meet): +1 upwards with q on its left, -1 downwards with q on its right;
  // counting an edge's lower end and not its upper one makes a ray through a vertex count once.
  int crossing(std::uint32_t k, const Point& q) {
    const Point &a = org(k), &b = dest(k);
    if (a.y <= q.y && q.y < b.y) return pred_.orient2d(a, b, q) > 0 ? 1 : 0;
    if (b.y <= q.y && q.y < a.y) return pred_.orient2d(a, b, q) < 0 ? -1 : 0;
    return 0;
  }

  const Mesh& mesh_;
  Predicates& pred_;
  std::vector<EdgeRef> boundary_;     // the boundary edges, in slot order
  std::vector<std::uint32_t> leaving_;  // per vertex: its boundary edge's index in boundary_, or kNone
  std::vector<std::uint32_t> next_, loop_;
  std::vector<Loop> loops_;
  std::uint32_t strips_ = 1;
  long double y0_ = 0, strip_h_ = 1;
  std::vector<std::size_t> strip_start_;
  std::vector<std::uint32_t> in_strip_;
};

}  // namespace

bool certify_embedding(const Mesh& mesh, Predicates& pred) { return Certificate(mesh, pred).run(); }

}  // namespace deltri
