// Angles and areas of a refined mesh (-q, -a): every triangle's smallest angle is at least the
// bound unless the input explains it, and no triangle is larger than the area bound.
//
// Small angles the input explains (the rules of MESHCHECK.md's quality item, written anew):
// 1. a corner at a vertex where input segments meet, inside the angle between two neighbouring
//    segments there when that angle is under 60 degrees: no mesh does better inside it;
// 2. a shortest edge joining points on two input segments that meet (at a shared end, an end of
//    one lying on the other, or a crossing) at an angle under 60 degrees, neither end being the
//    meeting point: the wedge between them;
// 3. a shortest edge joining points on two segments that meet, at distances from the meeting
//    point equal within 1%: the isosceles triangles of concentric shells (Miller, Pav and
//    Walkington's exemption; Triangle 1.6 applies it at any junction angle), unless that edge is
//    itself part of a segment.
// Angles come from atan2 of the cross and dot products in long double, with 1e-9 degrees of slack;
// areas likewise, with a relative slack of 1e-12. Whether a corner lies inside a sector is exact.
#include <algorithm>
#include <cmath>
#include <numbers>

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
  explicit Explainer(Context& c) : c_(c) {}

  bool explains(int t) {
    const std::array<int, 3>& v = c_.out.triangles[t];
    for (int i = 0; i < 3; ++i)
      if (corner_in_small_sector(v[i], v[(i + 1) % 3], v[(i + 2) % 3])) return true;
    int a = v[0], b = v[1];
    long double shortest = distance(c_.out.points[a], c_.out.points[b]);
    for (int i = 1; i < 3; ++i) {
      const int p = v[i], q = v[(i + 1) % 3];
      const long double d = distance(c_.out.points[p], c_.out.points[q]);
      if (d < shortest) shortest = d, a = p, b = q;
    }
    return shortest_edge_explained(a, b);
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

  // Where segments s1 and s2 meet: shared ends, an end of one on the other, or a proper crossing.
  std::vector<Point> meeting_points(int s1, int s2) {
    const Point &a = in_point(c_.in.segments[s1].a), &b = in_point(c_.in.segments[s1].b);
    const Point &d = in_point(c_.in.segments[s2].a), &e = in_point(c_.in.segments[s2].b);
    std::vector<Point> meet;
    for (const Point* p : {&a, &b})
      if (on_closed_segment(c_.pred, d, e, *p)) meet.push_back(*p);
    for (const Point* p : {&d, &e})
      if (on_closed_segment(c_.pred, a, b, *p) && std::find(meet.begin(), meet.end(), *p) == meet.end())
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

  // Rules 2 and 3.
  bool shortest_edge_explained(int a, int b) {
    const bool on_a_segment = c_.segment_edges.count(undirected_key(a, b)) != 0;
    for (int s1 : c_.segments_at[a])
      for (int s2 : c_.segments_at[b]) {
        if (s1 == s2) continue;
        for (const Point& j : meeting_points(s1, s2)) {
          // An edge with an end at j lies along a segment and spans no wedge (rule 1 or nothing).
          if (c_.out.points[a] == j || c_.out.points[b] == j) continue;
          if (meeting_angle(s1, s2, j) < kSmallInputAngle) return true;
          const long double da = distance(c_.out.points[a], j), db = distance(c_.out.points[b], j);
          if (!on_a_segment && da > 0 && db > 0 && std::fabs(da - db) <= 0.01L * std::max(da, db)) return true;
        }
      }
    return false;
  }

  Context& c_;
};

}  // namespace

void check_quality(Context& c, Failures& f, double min_angle_deg, double max_area) {
  Explainer explainer(c);
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
    if (smallest >= min_angle_deg - 1e-9L || explainer.explains(static_cast<int>(t))) continue;
    f.add("angle", "triangle " + std::to_string(t) + " " + fmt(p) + " " + fmt(q) + " " + fmt(r) +
                       " has a " + std::to_string(static_cast<double>(smallest)) + " degree angle, below " +
                       std::to_string(min_angle_deg) + " and not explained by the input");
  }
}

}  // namespace mv
