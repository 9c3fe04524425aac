// Angles and areas of a refined mesh (-q, -a): every triangle's smallest angle is at least the
// bound unless the input explains it, and no triangle is larger than the area bound.
//
// Small angles the input explains: those an input angle phi under 60 degrees forces, at the vertex j
// where two input segments meet (a shared end, an end of one lying on the other, or a crossing)
// (docs/manual.md, "Quality accounting"; the rules of deltri's account, written anew):
// 1. a corner at j, inside the angle between two neighbouring segments there when that angle is
//    under 60 degrees: no mesh does better inside the input angle itself;
// and, where the triangle's smallest angle is at least the floor of Theorem 12 of Shewchuk's paper
// (Sec. 6.3), arcsin(sin(phi / 2) / sqrt 2), below which the Terminator leaves no triangle:
// 2. a shortest edge joining points on two segments that meet at j at phi, neither end being j,
//    with the third corner in the corner triangle that edge cuts off at j (the concentric shells
//    around the input angle), or, where phi is below the -q angle, with its ends at distances from
//    j equal within 0.1% (a shell edge: Triangle and the Terminator spare every triangle on it);
// 3. a circumcentre in the closed diametral disk of a mesh edge that covers a segment and has an
//    end at j, where that segment bounds a sector of phi under 60 degrees between neighbouring
//    segments at j (the triangles the Terminator may decline, the proof of Theorem 12).
// A shortest edge merely spanning a wedge far from its apex, or joining points at equal distances
// from a junction at or above the -q angle, explains nothing: nothing forces a triangle there.
// Angles come from atan2 of the cross and dot products in long double, with 1e-9 degrees of slack;
// areas likewise, with a relative slack of 1e-12. Whether a corner lies inside a sector or a corner
// triangle is exact; the circumcentre and the disk test are in long double with a relative slack
// of 1e-12.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <vector>

#include "verify.h"

namespace mv {
namespace {

constexpr long double kSmallInputAngle = 60.0L;

long double angle_deg(const Point& o, const Point& p, const Point& q) {
  const long double ux = static_cast<long double>(p.x) - o.x, uy = static_cast<long double>(p.y) - o.y;
  const long double vx = static_cast<long double>(q.x) - o.x, vy = static_cast<long double>(q.y) - o.y;
  return std::atan2(std::fabs(ux * vy - uy * vx), ux * vx + uy * vy) * 180.0L / std::numbers::pi_v<long double>;
}

long double distance(const Point& a, const Point& b) {
  return std::hypot(static_cast<long double>(a.x) - b.x, static_cast<long double>(a.y) - b.y);
}

class Explainer {
 public:
  Explainer(Context& c, long double bound_deg) : c_(c), bound_deg_(bound_deg) {}

  bool explains(int t, long double smallest) {
    const std::array<int, 3>& v = c_.out.triangles[t];
    for (int i = 0; i < 3; ++i)
      if (corner_in_small_sector(v[i], v[(i + 1) % 3], v[(i + 2) % 3])) return true;
    int a = v[0], b = v[1], r = v[2];
    long double shortest = distance(c_.out.points[a], c_.out.points[b]);
    for (int i = 1; i < 3; ++i) {
      const int p = v[i], q = v[(i + 1) % 3];
      const long double d = distance(c_.out.points[p], c_.out.points[q]);
      if (d < shortest) shortest = d, a = p, b = q, r = v[(i + 2) % 3];
    }
    return shortest_edge_explained(a, b, r, smallest) || circumcentre_explained(t, smallest);
  }

 private:
  const Point& in_point(int i) const { return c_.in.points[i]; }

  // The input points that give the directions of segment s away from p (one or both ends).
  std::vector<int> ends_away_from(int s, const Point& p) const {
    std::vector<int> ends;
    for (int e : {c_.in.segments[s].a, c_.in.segments[s].b})
      if (!(in_point(e) == p)) ends.push_back(e);
    return ends;
  }

  // Rule 1: both other corners inside a sector under 60 degrees between neighbouring segments at v.
  bool corner_in_small_sector(int v, int q, int r) {
    const Point& o = c_.out.points[v];
    std::vector<int> dirs;
    for (int s : c_.segments_at[v])
      for (int e : ends_away_from(s, o)) dirs.push_back(e);
    if (dirs.size() < 2) return false;
    const auto theta = [&](int e) { return std::atan2(in_point(e).y - o.y, in_point(e).x - o.x); };
    std::sort(dirs.begin(), dirs.end(), [&](int x, int y) { return theta(x) < theta(y); });
    for (std::size_t k = 0; k < dirs.size(); ++k) {
      const Point& d1 = in_point(dirs[k]);
      const Point& d2 = in_point(dirs[(k + 1) % dirs.size()]);
      if (dirs.size() == 2 && k == 1) break;  // two directions: one sector each way, tried below
      for (const auto& [lo, hi] : {std::pair{&d1, &d2}, std::pair{&d2, &d1}}) {
        if (c_.pred.orient2d(o, *lo, *hi) < 0 || angle_deg(o, *lo, *hi) >= kSmallInputAngle) continue;
        bool inside = true;
        for (int z : {q, r}) {
          const Point& pz = c_.out.points[z];
          inside = inside && c_.pred.orient2d(o, *lo, pz) >= 0 && c_.pred.orient2d(o, pz, *hi) >= 0;
        }
        if (inside) return true;
      }
    }
    return false;
  }

  // An input point a few ulps off segment s that deltri's snapping put on it (the segment walk
  // found its vertex on s, verify_segments.cpp): an end of one segment on the other as well.
  bool snapped_onto(const Point& p, int s) const {
    const auto it = c_.topo.used_at.find(p);
    if (it == c_.topo.used_at.end()) return false;
    const std::vector<int>& on = c_.segments_at[it->second];
    return std::find(on.begin(), on.end(), s) != on.end();
  }

  // Where segments s1 and s2 meet: shared ends, an end of one on the other (snapped onto it
  // included), or a proper crossing.
  std::vector<Point> meeting_points(int s1, int s2) {
    const Point &a = in_point(c_.in.segments[s1].a), &b = in_point(c_.in.segments[s1].b);
    const Point &d = in_point(c_.in.segments[s2].a), &e = in_point(c_.in.segments[s2].b);
    std::vector<Point> meet;
    for (const Point* p : {&a, &b})
      if (on_closed_segment(c_.pred, d, e, *p) || snapped_onto(*p, s2)) meet.push_back(*p);
    for (const Point* p : {&d, &e})
      if ((on_closed_segment(c_.pred, a, b, *p) || snapped_onto(*p, s1)) && std::find(meet.begin(), meet.end(), *p) == meet.end())
        meet.push_back(*p);
    if (!meet.empty()) return meet;
    if (properly_cross(c_.pred, a, b, d, e)) {
      const double o1 = c_.pred.orient2d(a, b, d), o2 = c_.pred.orient2d(a, b, e);
      const double t = o1 / (o1 - o2);
      meet.push_back({d.x + t * (e.x - d.x), d.y + t * (e.y - d.y)});
    }
    return meet;
  }

  // The smallest angle between s1 and s2 at their meeting point j.
  long double meeting_angle(int s1, int s2, const Point& j) {
    long double smallest = 180.0L;
    for (int e1 : ends_away_from(s1, j))
      for (int e2 : ends_away_from(s2, j)) smallest = std::min(smallest, angle_deg(j, in_point(e1), in_point(e2)));
    return smallest;
  }

  static long double floor_deg(long double phi_deg) {
    const long double half = phi_deg / 2.0L * std::numbers::pi_v<long double> / 180.0L;
    return std::asin(std::sin(half) / std::numbers::sqrt2_v<long double>) * 180.0L / std::numbers::pi_v<long double>;
  }

  // Rule 2: r in the closed corner triangle j, a, b (r may be j).
  bool in_corner(const Point& j, const Point& a, const Point& b, const Point& r) {
    if (r == j) return true;
    const double turn = c_.pred.orient2d(j, a, b);
    if (turn == 0) return false;
    const double side = turn > 0 ? 1.0 : -1.0;
    return side * c_.pred.orient2d(j, a, r) >= 0 && side * c_.pred.orient2d(a, b, r) >= 0 &&
           side * c_.pred.orient2d(b, j, r) >= 0;
  }

  bool shortest_edge_explained(int a, int b, int r, long double smallest) {
    for (int s1 : c_.segments_at[a])
      for (int s2 : c_.segments_at[b]) {
        if (s1 == s2) continue;
        for (const Point& j : meeting_points(s1, s2)) {
          // An edge with an end at j lies along a segment and spans no wedge (rule 1 or nothing).
          if (c_.out.points[a] == j || c_.out.points[b] == j) continue;
          const long double phi = meeting_angle(s1, s2, j);
          if (phi >= kSmallInputAngle || smallest < floor_deg(phi) - 1e-9L) continue;
          if (in_corner(j, c_.out.points[a], c_.out.points[b], c_.out.points[r])) return true;
          const long double da = distance(c_.out.points[a], j), db = distance(c_.out.points[b], j);
          if (phi < bound_deg_ && std::fabs(da - db) <= 0.001L * std::max(da, db)) return true;
        }
      }
    return false;
  }

  // Rule 3's edges: a mesh edge covering a segment, from a vertex j where segments meet, which
  // bounds a sector under 60 degrees between neighbouring segments there; phi the smallest such.
  struct ClusterEdge {
    Point j, w;
    long double phi;
  };

  // The ccw angle in degrees from direction j->p to direction j->q, in [0, 360).
  static long double ccw_deg(const Point& j, const Point& p, const Point& q) {
    const long double a = std::atan2(static_cast<long double>(p.y) - j.y, static_cast<long double>(p.x) - j.x);
    const long double b = std::atan2(static_cast<long double>(q.y) - j.y, static_cast<long double>(q.x) - j.x);
    long double d = (b - a) * 180.0L / std::numbers::pi_v<long double>;
    while (d < 0) d += 360.0L;
    while (d >= 360.0L) d -= 360.0L;
    return d;
  }

  const std::vector<ClusterEdge>& cluster_edges() {
    if (cluster_edges_) return *cluster_edges_;
    cluster_edges_.emplace();
    for (std::size_t v = 0; v < c_.out.points.size(); ++v) {
      if (c_.segments_at[v].size() < 2) continue;
      const Point& o = c_.out.points[v];
      std::vector<int> dirs;
      for (int s : c_.segments_at[v])
        for (int e : ends_away_from(s, o)) dirs.push_back(e);
      if (dirs.size() < 2) continue;
      const auto theta = [&](int e) { return std::atan2(in_point(e).y - o.y, in_point(e).x - o.x); };
      std::sort(dirs.begin(), dirs.end(), [&](int x, int y) { return theta(x) < theta(y); });
      for (int w : c_.topo.adjacent[v]) {
        if (c_.segment_edges.count(undirected_key(static_cast<int>(v), w)) == 0) continue;
        const Point& pw = c_.out.points[w];
        long double phi = kSmallInputAngle;
        for (std::size_t k = 0; k < dirs.size(); ++k) {
          const Point& d = in_point(dirs[k]);
          if (c_.pred.orient2d(o, d, pw) != 0 ||
              (static_cast<long double>(d.x) - o.x) * (pw.x - o.x) + (static_cast<long double>(d.y) - o.y) * (pw.y - o.y) <= 0)
            continue;
          const long double after = ccw_deg(o, d, in_point(dirs[(k + 1) % dirs.size()]));
          const long double before = ccw_deg(o, in_point(dirs[(k + dirs.size() - 1) % dirs.size()]), d);
          for (long double gap : {after, before})
            if (gap > 0 && gap < phi) phi = gap;
        }
        if (phi < kSmallInputAngle) cluster_edges_->push_back({o, pw, phi});
      }
    }
    return *cluster_edges_;
  }

  // Rule 3.
  bool circumcentre_explained(int t, long double smallest) {
    const Point &p = c_.tri_point(t, 0), &q = c_.tri_point(t, 1), &r = c_.tri_point(t, 2);
    const long double bx = static_cast<long double>(q.x) - p.x, by = static_cast<long double>(q.y) - p.y;
    const long double cx = static_cast<long double>(r.x) - p.x, cy = static_cast<long double>(r.y) - p.y;
    const long double d = 2 * (bx * cy - by * cx);
    if (d == 0) return false;
    const long double b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
    const long double ux = p.x + (cy * b2 - by * c2) / d, uy = p.y + (bx * c2 - cx * b2) / d;
    for (const ClusterEdge& e : cluster_edges()) {
      if (smallest < floor_deg(e.phi) - 1e-9L) continue;
      const long double mx = (static_cast<long double>(e.j.x) + e.w.x) / 2, my = (static_cast<long double>(e.j.y) + e.w.y) / 2;
      const long double rx = (static_cast<long double>(e.w.x) - e.j.x) / 2, ry = (static_cast<long double>(e.w.y) - e.j.y) / 2;
      if ((ux - mx) * (ux - mx) + (uy - my) * (uy - my) <= (rx * rx + ry * ry) * (1 + 1e-12L)) return true;
    }
    return false;
  }

  Context& c_;
  long double bound_deg_;
  std::optional<std::vector<ClusterEdge>> cluster_edges_;
};

}  // namespace

void check_quality(Context& c, Failures& f, double min_angle_deg, double max_area) {
  Explainer explainer(c, min_angle_deg);
  for (std::size_t t = 0; t < c.out.triangles.size(); ++t) {
    const Point p = c.tri_point(t, 0), q = c.tri_point(t, 1), r = c.tri_point(t, 2);
    if (max_area > 0) {
      const long double area = 0.5L * std::fabs((static_cast<long double>(q.x) - p.x) * (static_cast<long double>(r.y) - p.y) -
                                                (static_cast<long double>(q.y) - p.y) * (static_cast<long double>(r.x) - p.x));
      if (area > max_area * (1.0L + 1e-12L))
        f.add("area", "triangle " + std::to_string(t) + " has area " + std::to_string(static_cast<double>(area)) +
                          " > " + std::to_string(max_area));
    }
    if (min_angle_deg <= 0) continue;
    const long double smallest = std::min({angle_deg(p, q, r), angle_deg(q, r, p), angle_deg(r, p, q)});
    if (smallest >= min_angle_deg - 1e-9L || explainer.explains(static_cast<int>(t), smallest)) continue;
    f.add("angle", "triangle " + std::to_string(t) + " " + fmt(p) + " " + fmt(q) + " " + fmt(r) +
                       " has a " + std::to_string(static_cast<double>(smallest)) + " degree angle, below " +
                       std::to_string(min_angle_deg) + " and not explained by the input");
  }
}

}  // namespace mv
