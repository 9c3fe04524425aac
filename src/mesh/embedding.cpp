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

// Half-turns round c from the direction +x: 0 for directions in [0, pi), 1 for [pi, 2 pi).
int half(const Point& c, const Point& a) { return a.y > c.y || (a.y == c.y && a.x > c.x) ? 0 : 1; }

// For a, v, w on one line with a and w apart from v: w lies on a's side of v.
bool same_side(const Point& v, const Point& a, const Point& w) {
  return (a.x < v.x) == (w.x < v.x) && (a.x > v.x) == (w.x > v.x) && (a.y < v.y) == (w.y < v.y) &&
         (a.y > v.y) == (w.y > v.y);
}

// A boundary edge at a bow tie: k for edge k leaving it, ~k for edge k reaching it.
constexpr std::uint32_t kLastIndex = 0x7FFFFFFFu;
// leaving_ of a vertex left by several boundary edges.
constexpr std::uint32_t kTie = 0xFFFFFFFEu;

class Certificate {
 public:
  Certificate(const Mesh& mesh, Predicates& pred) : mesh_(mesh), pred_(pred) {}

  bool run() {
    return collect_boundary() && pair_at_ties() && trace_loops() && corners_turn() && no_edges_meet() && loops_nest();
  }

 private:
  struct Loop {
    std::uint32_t lowest;  // the boundary edge ending at the loop's lowest vertex
  };

  const Point& org(std::uint32_t k) const { return mesh_.point(mesh_.org(boundary_[k])); }
  const Point& dest(std::uint32_t k) const { return mesh_.point(mesh_.dest(boundary_[k])); }
  // The work allowed to the parts that are not linear in the worst case; past it the certificate
  // gives up (it is meant to cost little next to the pair search, which then decides).
  std::size_t budget() const { return 16 * boundary_.size() + 4096; }

  // The edges without a twin. A vertex left by more than one (a "bow tie") is listed in ties_.
  bool collect_boundary() {
    leaving_.assign(mesh_.vertex_count(), kNone);
    for (EdgeRef e{0}; e < mesh_.corner.size(); ++e) {
      if (!mesh_.is_live(triangle_of(e)) || mesh_.link[e] != kNone) continue;
      std::uint32_t& out = leaving_[mesh_.org(e)];
      if (out != kNone && out != kTie) ties_.push_back(mesh_.org(e));
      out = out == kNone ? static_cast<std::uint32_t>(boundary_.size()) : kTie;
      boundary_.push_back(e);
    }
    next_.assign(boundary_.size(), kNone);
    // Triangles without a boundary cannot all be counter-clockwise.
    return !boundary_.empty() && boundary_.size() <= kLastIndex;
  }

  // At each bow tie v, its boundary edges (leaving and reaching it) in counter-clockwise order
  // round v must alternate, leaving and reaching, in pairwise different directions; each edge
  // reaching v is then followed by the one leaving v just clockwise of it, with which it bounds a
  // sector round v that holds no other boundary edge and lies on the left of both.
  bool pair_at_ties() {
    if (ties_.empty()) return true;
    gather_tie_edges();
    for (std::uint32_t i = 0; i < ties_.size(); ++i)
      if (!pair_round(ties_[i], tie_start_[i], tie_start_[i + 1])) return false;
    return true;
  }

  // tie_edges_[tie_start_[i] ..] : the boundary edges at ties_[i], as k (leaving) or ~k (reaching).
  void gather_tie_edges() {
    tie_of_.assign(mesh_.vertex_count(), kNone);
    for (std::uint32_t i = 0; i < ties_.size(); ++i) tie_of_[ties_[i]] = i;
    tie_start_.assign(ties_.size() + 1, 0);
    const auto each_end = [&](auto&& visit) {
      for (std::uint32_t k = 0; k < boundary_.size(); ++k) {
        if (const std::uint32_t i = tie_of_[mesh_.org(boundary_[k])]; i != kNone) visit(i, k);
        if (const std::uint32_t i = tie_of_[mesh_.dest(boundary_[k])]; i != kNone) visit(i, ~k);
      }
    };
    each_end([&](std::uint32_t i, std::uint32_t) { ++tie_start_[i + 1]; });
    for (std::uint32_t i = 0; i < ties_.size(); ++i) tie_start_[i + 1] += tie_start_[i];
    tie_edges_.resize(tie_start_.back());
    std::vector<std::uint32_t> fill(tie_start_.begin(), tie_start_.end() - 1);
    each_end([&](std::uint32_t i, std::uint32_t end) { tie_edges_[fill[i]++] = end; });
  }

  // The far end of a tie edge as seen from its tie vertex.
  const Point& far_end(std::uint32_t end) const { return end <= kLastIndex ? dest(end) : org(~end); }

  // The edges tie_edges_[first, last) at v, sorted round it, checked and paired.
  bool pair_round(VertexId v, std::uint32_t first, std::uint32_t last) {
    const Point& c = mesh_.point(v);
    const auto begin = tie_edges_.begin() + first, end = tie_edges_.begin() + last;
    std::sort(begin, end, [&](std::uint32_t a, std::uint32_t b) { return turns_before(c, far_end(a), far_end(b)); });
    const std::uint32_t n = last - first;
    for (std::uint32_t i = 0; i < n; ++i) {
      const std::uint32_t a = begin[i], b = begin[(i + 1) % n];
      if ((a <= kLastIndex) == (b <= kLastIndex)) return false;                 // not alternating
      if (i + 1 < n && !turns_before(c, far_end(a), far_end(b))) return false;  // one direction
      if (b > kLastIndex) next_[~b] = a;
    }
    return true;
  }

  // Exact angular order round c, from the direction +x counter-clockwise (a strict weak order;
  // two ends in one direction from c are equivalent).
  bool turns_before(const Point& c, const Point& a, const Point& b) {
    const int ha = half(c, a), hb = half(c, b);
    return ha != hb ? ha < hb : pred_.orient2d(c, a, b) > 0;
  }

  // next_[k]: the boundary edge after k; loops_: one entry per loop. Twins pair each arrival at a vertex
  // with a departure, so a vertex left by one boundary edge is reached by one, and the loops close.
  bool trace_loops() {
    for (std::uint32_t k = 0; k < boundary_.size(); ++k)
      if (const std::uint32_t out = leaving_[mesh_.dest(boundary_[k])]; out != kTie) next_[k] = out;
    std::vector<char> seen(boundary_.size(), 0);
    for (std::uint32_t k = 0; k < boundary_.size(); ++k) {
      if (seen[k]) continue;
      loops_.push_back({k});
      std::uint32_t j = k;
      for (; j != kNone && !seen[j]; j = next_[j]) {
        seen[j] = 1;
        if (lower(dest(j), dest(loops_.back().lowest))) loops_.back().lowest = j;
      }
      if (j != k) return false;  // not a permutation: the twins were not as promised
    }
    return true;
  }

  // Consecutive boundary edges a->v, v->w meet only at v unless w lies along v->a (at a bow tie
  // pair_round has seen to it already).
  bool corners_turn() {
    for (std::uint32_t k = 0; k < boundary_.size(); ++k) {
      const Point &a = org(k), &v = dest(k), &w = dest(next_[k]);
      if (pred_.orient2d(a, v, w) == 0 && same_side(v, a, w)) return false;
    }
    return true;
  }

  // Boundary edges with no endpoint in common are disjoint (two with one in common leave it in
  // different directions: corners_turn, pair_round; so they meet only there).
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

  // (W) of embedding.h. One loop without bow ties is a simple polygon: it must run
  // counter-clockwise, as its lowest vertex (a convex corner, not flat by corners_turn) tells.
  bool loops_nest() {
    if (loops_.size() == 1 && ties_.empty()) {
      const Loop& l = loops_[0];
      return pred_.orient2d(org(l.lowest), dest(l.lowest), dest(next_[l.lowest])) > 0;
    }
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

  // W just left of each loop, at its lowest vertex q where its edge k arrives and next_[k]
  // leaves, must be 1: W on the sector just counter-clockwise of the direction +x at q (the ray
  // crossings of all boundary edges, those at q counting 0), then one up for each boundary edge
  // leaving q and one down for each reaching q, met turning from there to next_[k].
  bool windings_fit() {
    std::size_t scanned = 0;
    for (const Loop& l : loops_) {
      const Point& q = dest(l.lowest);
      const std::uint32_t r = strip(q.y);
      if ((scanned += strip_start_[r + 1] - strip_start_[r]) > budget()) return false;
      int winding = 0;
      for (std::size_t i = strip_start_[r]; i < strip_start_[r + 1]; ++i) winding += crossing(in_strip_[i], q);
      if (winding + turned_past(l.lowest) != 1) return false;
    }
    return true;
  }

  // The boundary edges at q = dest(k) in directions in (0, angle of next_[k]] from +x: +1 for
  // each leaving q, -1 for each reaching it.
  int turned_past(std::uint32_t k) {
    const Point &q = dest(k), &w = dest(next_[k]);
    const auto passed = [&](const Point& a) { return !(a.y == q.y && a.x > q.x) && !turns_before(q, w, a); };
    const VertexId v = mesh_.dest(boundary_[k]);
    if (leaving_[v] != kTie) return passed(w) - passed(org(k));
    int sum = 0;
    const std::uint32_t i = tie_of_[v];
    for (std::uint32_t j = tie_start_[i]; j < tie_start_[i + 1]; ++j) {
      const std::uint32_t end = tie_edges_[j];
      if (passed(far_end(end))) sum += end <= kLastIndex ? 1 : -1;
    }
    return sum;
  }

  // Edge k's signed crossing of the ray towards +x from q, which no boundary edge but those at q
  // meets (no_edges_meet): +1 upwards with q on its left, -1 downwards with q on its right;
  // counting an edge's lower end and not its upper one makes a ray through a vertex count once.
  // That is the crossing of the ray from q + (e, e d) for 0 < d << e small: the ray from a point
  // just counter-clockwise of +x at q, which crosses no edge at q (those give orient2d 0 here).
  int crossing(std::uint32_t k, const Point& q) {
    const Point &a = org(k), &b = dest(k);
    if (a.y <= q.y && q.y < b.y) return pred_.orient2d(a, b, q) > 0 ? 1 : 0;
    if (b.y <= q.y && q.y < a.y) return pred_.orient2d(a, b, q) < 0 ? -1 : 0;
    return 0;
  }

  const Mesh& mesh_;
  Predicates& pred_;
  std::vector<EdgeRef> boundary_;     // the boundary edges, in slot order
  std::vector<std::uint32_t> leaving_;  // per vertex: its boundary edge's index in boundary_, kNone or kTie
  std::vector<VertexId> ties_;          // the vertices left by several boundary edges
  std::vector<std::uint32_t> tie_of_, tie_start_, tie_edges_;
  std::vector<std::uint32_t> next_;
  std::vector<Loop> loops_;
  std::uint32_t strips_ = 1;
  long double y0_ = 0, strip_h_ = 1;
  std::vector<std::size_t> strip_start_;
  std::vector<std::uint32_t> in_strip_;
};

}  // namespace

bool certify_embedding(const Mesh& mesh, Predicates& pred) { return Certificate(mesh, pred).run(); }

}  // namespace deltri
