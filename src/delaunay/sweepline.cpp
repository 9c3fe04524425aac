#include "delaunay/sweepline.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <queue>

#include "delaunay/incremental.h"
#include "delaunay/lawson_pass.h"
#include "mesh/assemble.h"

namespace deltri {
namespace {

constexpr std::uint32_t kNoArc = 0xFFFFFFFFu;

// One arc of the beach line. Arcs are never freed during a sweep: a dead arc keeps its `next`, so
// a stale hint still leads to a live arc.
struct Arc {
  VertexId site;
  std::uint32_t prev = kNoArc, next = kNoArc;
  std::uint32_t stamp = 0;  // bumped whenever the arc's pending circle event becomes stale
  bool alive = true;
  // The breakpoint between this arc and the previous one traces the Voronoi edge dual to the
  // Delaunay edge of their two sites: an index into Sweep::ends_, where the triangle edge made at
  // one end of that Voronoi edge waits for its twin, made at the other end.
  std::uint32_t left_end = kNoArc;
};

// The arc `arc` vanishes when the sweep line reaches y (the top of the circle through its site
// and its two neighbours'), at x.
struct CircleEvent {
  double y, x;
  std::uint32_t arc, stamp;
};
struct Later {
  bool operator()(const CircleEvent& a, const CircleEvent& b) const { return a.y != b.y ? a.y > b.y : a.x > b.x; }
};

class Sweep {
 public:
  Sweep(Mesh& mesh, Predicates& pred, double lo_x, double hi_x, std::size_t sites)
      : mesh_(mesh), pred_(pred), lo_x_(lo_x) {
    const std::size_t buckets = std::max<std::size_t>(1, static_cast<std::size_t>(std::sqrt(static_cast<double>(sites))));
    hints_.assign(buckets, 0);
    scale_ = hi_x > lo_x ? static_cast<double>(buckets) / (hi_x - lo_x) : 0.0;
    arcs_.reserve(2 * sites + 1);
    ends_.reserve(sites * 3);
    reserve_triangles(mesh_, 2 * sites);
  }

  // `sites` sorted by y, then x. The triangles are appended to the mesh, linked to each other;
  // false if a link joined edges that are not twins (rounding broke the sweep).
  bool run(const std::vector<VertexId>& sites) {
    std::size_t i = 0;
    arcs_.push_back({sites[0]});
    const double first_y = point(sites[0]).y;
    // Sites level with the first: their parabolas are vertical rays, side by side in x order.
    for (i = 1; i < sites.size() && point(sites[i]).y == first_y; ++i) {
      const std::uint32_t left = static_cast<std::uint32_t>(arcs_.size() - 1);
      arcs_.push_back({sites[i], left, kNoArc, 0, true, new_end(kNone)});
      arcs_[left].next = left + 1;
      hint(point(sites[i]).x) = left + 1;
    }
    while (i < sites.size() || !events_.empty()) {
      const bool circle_first = !events_.empty() && (i == sites.size() || events_.top().y < point(sites[i]).y ||
                                                     (events_.top().y == point(sites[i]).y && events_.top().x < point(sites[i]).x));
      if (circle_first) {
        const CircleEvent e = events_.top();
        events_.pop();
        circle_event(e);
      } else {
        site_event(sites[i++]);
      }
    }
    return consistent_;
  }

 private:
  const Point& point(VertexId v) const { return mesh_.points[v]; }
  std::uint32_t& hint(double x) {
    const double b = (x - lo_x_) * scale_;
    const std::size_t k = b <= 0.0 ? 0 : std::min(hints_.size() - 1, static_cast<std::size_t>(b));
    return hints_[k];
  }

  // Where the arc of site a (on the left) meets the arc of site b (on its right) when the sweep line
  // is at l. With a at the origin, b at (dx, dy) and L = l - a.y, M = l - b.y, the parabolas meet
  // where dy u^2 - 2 L dx u + L (dx^2 + dy^2) - dy L^2 = 0; the root that has a's arc on its left is
  // u = (L dx - S) / dy = L (dx^2 - M dy) / (L dx + S) with S = sqrt(L M (dx^2 + dy^2)), the second
  // form free of cancellation when dx >= 0.
  double breakpoint(VertexId a, VertexId b, double l) const {
    const Point& pa = point(a);
    const Point& pb = point(b);
    if (pa.y == pb.y) return 0.5 * (pa.x + pb.x);
    if (pa.y >= l) return pa.x;
    if (pb.y >= l) return pb.x;
    const long double dx = static_cast<long double>(pb.x) - pa.x, dy = static_cast<long double>(pb.y) - pa.y;
    const long double L = static_cast<long double>(l) - pa.y, M = static_cast<long double>(l) - pb.y;
    const long double S = std::sqrt(L * M * (dx * dx + dy * dy));
    const long double u = dx >= 0 ? L * (dx * dx - M * dy) / (L * dx + S) : (L * dx - S) / dy;
    return static_cast<double>(pa.x + u);
  }

  std::uint32_t find_arc(double x, double l) {
    std::uint32_t h = hint(x);
    while (h != kNoArc && !arcs_[h].alive) h = arcs_[h].next;
    if (h == kNoArc) h = 0;  // the leftmost arc never vanishes
    while (arcs_[h].prev != kNoArc && x < breakpoint(arcs_[arcs_[h].prev].site, arcs_[h].site, l)) h = arcs_[h].prev;
    while (arcs_[h].next != kNoArc && x > breakpoint(arcs_[h].site, arcs_[arcs_[h].next].site, l)) h = arcs_[h].next;
    return h;
  }

  // A site splits the arc above it into two, with its own (of no width yet) between them.
  void site_event(VertexId s) {
    const Point& p = point(s);
    const std::uint32_t a = find_arc(p.x, p.y);
    ++arcs_[a].stamp;
    const std::uint32_t mid = static_cast<std::uint32_t>(arcs_.size());
    const std::uint32_t right = mid + 1;
    const std::uint32_t after = arcs_[a].next;
    // The two new breakpoints move apart from the site: the two ends of one Voronoi edge.
    const std::uint32_t end = new_end(kNone);
    arcs_.push_back({s, a, right, 0, true, end});
    arcs_.push_back({arcs_[a].site, mid, after, 0, true, end});
    if (after != kNoArc) arcs_[after].prev = right;
    arcs_[a].next = mid;
    hint(p.x) = mid;
    check_circle(a, p.y);
    check_circle(right, p.y);
  }

  // The arc shrank to nothing: its site and its neighbours' make a Delaunay triangle. Its edges
  // a-b and b-c end the Voronoi edges traced by the two breakpoints that met here, and its edge
  // c-a starts the one traced by the new breakpoint between a and c.
  void circle_event(const CircleEvent& e) {
    Arc& b = arcs_[e.arc];
    if (!b.alive || b.stamp != e.stamp) return;
    const std::uint32_t a = b.prev, c = b.next;
    const TriangleId t = append_unlinked(mesh_, arcs_[a].site, b.site, arcs_[c].site);
    close(b.left_end, edge_of(t, 0));
    close(arcs_[c].left_end, edge_of(t, 1));
    arcs_[c].left_end = new_end(edge_of(t, 2));
    b.alive = false;
    arcs_[a].next = c;
    arcs_[c].prev = a;
    ++arcs_[a].stamp;
    ++arcs_[c].stamp;
    check_circle(a, e.y);
    check_circle(c, e.y);
  }

  std::uint32_t new_end(EdgeRef e) {
    ends_.push_back(e);
    return static_cast<std::uint32_t>(ends_.size() - 1);
  }

  // A breakpoint ended at a triangle with edge e: e's twin is the edge made at the Voronoi edge's
  // other end, or will be.
  void close(std::uint32_t end, EdgeRef e) {
    if (ends_[end] == kNone) {
      ends_[end] = e;
      return;
    }
    if (!pair_twins(mesh_, e, ends_[end])) consistent_ = false;
  }

  // Queues the event where arc b vanishes, if its neighbours' breakpoints converge on it: exactly
  // when its site and theirs turn counter-clockwise (left neighbour, b, right neighbour).
  void check_circle(std::uint32_t b, double l) {
    const std::uint32_t a = arcs_[b].prev, c = arcs_[b].next;
    if (a == kNoArc || c == kNoArc) return;
    const VertexId sa = arcs_[a].site, sb = arcs_[b].site, sc = arcs_[c].site;
    if (sa == sc || pred_.orient2d(point(sa), point(sb), point(sc)) <= 0) return;
    // Circumcentre relative to b, in long double; the event is at the circle's top.
    const Point& pb = point(sb);
    const long double ax = static_cast<long double>(point(sa).x) - pb.x, ay = static_cast<long double>(point(sa).y) - pb.y;
    const long double cx = static_cast<long double>(point(sc).x) - pb.x, cy = static_cast<long double>(point(sc).y) - pb.y;
    const long double d = 2 * (ax * cy - ay * cx);
    const long double a2 = ax * ax + ay * ay, c2 = cx * cx + cy * cy;
    const long double ux = (cy * a2 - ay * c2) / d, uy = (ax * c2 - cx * a2) / d;
    const double top = static_cast<double>(pb.y + uy + std::sqrt(ux * ux + uy * uy));
    events_.push({std::max(top, l), static_cast<double>(pb.x + ux), b, arcs_[b].stamp});
  }

  Mesh& mesh_;
  Predicates& pred_;
  bool consistent_ = true;
  double lo_x_, scale_ = 0.0;
  std::vector<Arc> arcs_;
  std::vector<EdgeRef> ends_;  // see Arc::left_end
  std::vector<std::uint32_t> hints_;  // per x bucket, an arc that was recently there
  std::priority_queue<CircleEvent, std::vector<CircleEvent>, Later> events_;
};

// Whether the boundary edges form one convex loop through every hull vertex, as a triangulation
// of n distinct points with h hull vertices has, with 2n - 2 - h triangles.
bool tiles_convex_hull(const Mesh& mesh, Predicates& pred, std::size_t distinct) {
  std::vector<EdgeRef> next_boundary(mesh.vertex_count(), kNone);
  std::size_t boundary = 0;
  for (EdgeRef e{0}; e < mesh.corner.size(); ++e)
    if (mesh.link[e] == kNone) {
      if (next_boundary[mesh.org(e)] != kNone) return false;
      next_boundary[mesh.org(e)] = e;
      ++boundary;
    }
  if (boundary < 3 || mesh.triangle_slots() + 2 + boundary != 2 * distinct) return false;
  // Walk the loop: it must close after `boundary` steps, turning left or going straight.
  const EdgeRef first = [&] {
    for (EdgeRef e{0}; e < mesh.corner.size(); ++e)
      if (mesh.link[e] == kNone) return e;
    return EdgeRef{kNone};
  }();
  EdgeRef e = first;
  for (std::size_t k = 0; k < boundary; ++k) {
    const EdgeRef f = next_boundary[mesh.dest(e)];
    if (f == kNone) return false;
    if (pred.orient2d(mesh.point(mesh.org(e)), mesh.point(mesh.dest(e)), mesh.point(mesh.dest(f))) < 0) return false;
    e = f;
  }
  return e == first;
}

}  // namespace

bool sweepline_delaunay(Mesh& mesh, Predicates& pred, std::vector<std::pair<VertexId, VertexId>>& duplicates) {
  std::vector<VertexId> sites = distinct_inputs(mesh, duplicates);
  if (sites.size() < 3) return true;
  // Sorted as (y, x, id) records: sorting ids through the point array misses the cache every time.
  struct Key {
    double y, x;
    VertexId id;
  };
  std::vector<Key> keys(sites.size());
  double lo = mesh.points[sites[0]].x, hi = lo;
  for (std::size_t k = 0; k < sites.size(); ++k) {
    const Point& q = mesh.points[sites[k]];
    keys[k] = {q.y, q.x, sites[k]};
    lo = std::min(lo, q.x), hi = std::max(hi, q.x);
  }
  std::sort(keys.begin(), keys.end(), [](const Key& a, const Key& b) { return a.y != b.y ? a.y < b.y : a.x < b.x; });
  for (std::size_t k = 0; k < sites.size(); ++k) sites[k] = keys[k].id;
  std::vector<Key>().swap(keys);
  Sweep sweep(mesh, pred, lo, hi, sites.size());
  const bool consistent = sweep.run(sites);
  if (mesh.corner.empty()) return true;  // all collinear
  if (!consistent || !tiles_convex_hull(mesh, pred, sites.size())) {
    clear_triangles(mesh);
    return false;
  }
  lawson_pass(mesh, pred);
  return true;
}

}  // namespace deltri
