// Constructions: circumcentres, radius-edge ratios, off-centres and segment crossings.
#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/constructions.h"
#include "geometry/exact_reference.h"
#include "geometry/random_support.h"
#include "harness/check.h"

namespace {

using deltri::Point;
using reference::orient_sign;
using testing_support::nudge;
using testing_support::Random;

double distance(const Point& a, const Point& b) { return std::sqrt(deltri::squared_distance(a, b)); }

double largest_coordinate(const Point& a, const Point& b, const Point& c) {
  return std::max({std::fabs(a.x), std::fabs(a.y), std::fabs(b.x), std::fabs(b.y), std::fabs(c.x),
                   std::fabs(c.y)});
}

// True if the line through a and b passes through the box of +-k ulps around p: the corners must
// not all lie strictly on one side (decided exactly).
bool line_within_ulps(const Point& a, const Point& b, const Point& p, int k) {
  bool positive = false, negative = false;
  for (int sx : {-k, k}) {
    for (int sy : {-k, k}) {
      const int s = orient_sign(a, b, nudge(p, sx, sy));
      positive |= s >= 0;
      negative |= s <= 0;
    }
  }
  return positive && negative;
}

}  // namespace

TEST(circumcenter_is_equidistant) {
  Random rng(40);
  const double offsets[] = {0.0, 1e9, -3e5};
  for (int i = 0; i < 10000; ++i) {
    const double offset = offsets[i % 3];
    const double size = std::pow(10.0, rng.integer(-3, 3));
    const Point a{offset + size * rng.uniform(-1, 1), offset + size * rng.uniform(-1, 1)};
    const Point b{offset + size * rng.uniform(-1, 1), offset + size * rng.uniform(-1, 1)};
    const Point c{offset + size * rng.uniform(-1, 1), offset + size * rng.uniform(-1, 1)};
    if (orient_sign(a, b, c) == 0) continue;
    const Point o = deltri::circumcenter(a, b, c);
    const double ra = distance(o, a), rb = distance(o, b), rc = distance(o, c);
    // Input rounding is a few ulps of the largest coordinate, magnified by the triangle's shape
    // (the circumradius over the shortest edge).
    const double ulp = largest_coordinate(a, b, c) * 0x1p-52;
    const double tolerance = 1e-12 * ra + 16 * ulp * deltri::radius_edge_ratio(a, b, c);
    CHECK_NEAR(ra, rb, tolerance);
    CHECK_NEAR(ra, rc, tolerance);
  }
}

TEST(circumcenter_of_thin_triangle_uses_accurate_denominator) {
  // Needles whose apex is a few ulps off the (slanted) base line: the floating-point cross product
  // cancels almost entirely, yet the centre must still be nearly equidistant.
  Random rng(44);
  for (int i = 0; i < 1000; ++i) {
    const Point a = rng.point(-1, 1), b = rng.point(-1, 1);
    const Point mid = testing_support::nudge(Point{(a.x + b.x) / 2, (a.y + b.y) / 2},
                                             rng.integer(-4, 4), rng.integer(-4, 4));
    if (orient_sign(a, b, mid) == 0) continue;
    const Point o = deltri::circumcenter(a, b, mid);
    const double ra = distance(o, a);
    CHECK_NEAR(distance(o, b) / ra, 1.0, 1e-6);
    CHECK_NEAR(distance(o, mid) / ra, 1.0, 1e-6);
    // Equidistance is insensitive to errors along the bisector, so also compare the radius with
    // |ab| |b mid| |mid a| / (2 |cross|), the cross product taken from the exact evaluator.
    const double cross = reference::orient_value(a, b, mid).approximate();
    const double expected = distance(a, b) * distance(b, mid) * distance(mid, a) / (2 * std::fabs(cross));
    CHECK_NEAR(ra / expected, 1.0, 1e-6);
  }
}

TEST(circumcenter_exact_cases) {
  const Point o = deltri::circumcenter({0, 0}, {2, 0}, {0, 2});
  CHECK_EQ(o.x, 1.0);
  CHECK_EQ(o.y, 1.0);
  const Point f = deltri::circumcenter({1e9 + 1, 1e9}, {1e9, 1e9 + 1}, {1e9 - 1, 1e9});
  CHECK_EQ(f.x, 1e9);
  CHECK_EQ(f.y, 1e9);
}

TEST(radius_edge_ratio_known_values) {
  CHECK_NEAR(deltri::radius_edge_ratio({0, 0}, {1, 0}, {0.5, std::sqrt(0.75)}), 1 / std::sqrt(3.0), 1e-15);
  CHECK_NEAR(deltri::radius_edge_ratio({0, 0}, {1, 0}, {0, 1}), std::sqrt(0.5), 1e-15);
  CHECK_NEAR(deltri::radius_edge_ratio_squared({0, 0}, {3, 0}, {0, 4}), 6.25 / 9.0, 1e-15);
  CHECK(std::isinf(deltri::radius_edge_ratio({0, 0}, {1, 1}, {2, 2})));
  // Ratio and 1 / (2 sin(smallest angle)) agree.
  Random rng(41);
  for (int i = 0; i < 2000; ++i) {
    const Point a = rng.point(-1, 1), b = rng.point(-1, 1), c = rng.point(-1, 1);
    auto angle = [](const Point& p, const Point& q, const Point& r) {
      const double ux = q.x - p.x, uy = q.y - p.y, vx = r.x - p.x, vy = r.y - p.y;
      return std::atan2(std::fabs(ux * vy - uy * vx), ux * vx + uy * vy);
    };
    const double smallest = std::min({angle(a, b, c), angle(b, c, a), angle(c, a, b)});
    if (smallest < 1e-3) continue;
    CHECK_NEAR(deltri::radius_edge_ratio(a, b, c) * 2 * std::sin(smallest), 1.0, 1e-9);
  }
}

TEST(off_center_gives_ratio_beta_on_shortest_edge) {
  Random rng(42);
  const double betas[] = {std::sqrt(2.0), 1.0, 0.8, 2.5};
  int off_centres = 0, circumcentres = 0;
  for (int i = 0; i < 10000; ++i) {
    const double beta = betas[i % 4];
    const Point a = rng.point(-1, 1), b = rng.point(-1, 1), c = rng.point(-1, 1);
    if (orient_sign(a, b, c) == 0 || deltri::radius_edge_ratio(a, b, c) > 1e6) continue;
    // Find the shortest edge pq and the opposite corner r.
    Point p = a, q = b, r = c;
    if (deltri::squared_distance(b, c) < deltri::squared_distance(p, q)) p = b, q = c, r = a;
    if (deltri::squared_distance(c, a) < deltri::squared_distance(p, q)) p = c, q = a, r = b;
    const Point x = deltri::off_center(a, b, c, beta);
    const Point centre = deltri::circumcenter(a, b, c);
    // The triangle on pq through the circumcentre has apex angle 2 * (angle at r); the off-centre
    // is used exactly when that apex is sharper than the apex t of ratio beta, sin t = 1 / (2 beta).
    const double ux = p.x - r.x, uy = p.y - r.y, vx = q.x - r.x, vy = q.y - r.y;
    const double angle_r = std::atan2(std::fabs(ux * vy - uy * vx), ux * vx + uy * vy);
    const double half_apex = 0.5 * std::asin(1 / (2 * beta));
    if (x == centre) {
      ++circumcentres;
      CHECK(angle_r >= half_apex - 1e-9);
      continue;
    }
    ++off_centres;
    CHECK(angle_r <= half_apex + 1e-9);
    CHECK_NEAR(deltri::radius_edge_ratio(p, q, x) / beta, 1.0, 1e-9);
    CHECK_NEAR(distance(x, p) / distance(x, q), 1.0, 1e-12);
    CHECK_EQ(orient_sign(p, q, x), orient_sign(p, q, r));
    // The off-centre lies between the edge and the circumcentre.
    const Point mid{(p.x + q.x) / 2, (p.y + q.y) / 2};
    CHECK(distance(mid, x) < distance(mid, centre));
    CHECK(deltri::radius_edge_ratio(a, b, c) > beta);
  }
  CHECK(off_centres > 1000);
  CHECK(circumcentres > 1000);
}

TEST(off_center_of_good_triangle_is_circumcenter) {
  const Point a{0, 0}, b{1, 0}, c{0.5, std::sqrt(0.75)};
  const Point centre = deltri::circumcenter(a, b, c);
  CHECK(deltri::off_center(a, b, c, std::sqrt(2.0)) == centre);
  CHECK(deltri::off_center(a, b, c, 0.4) == centre);
  // A needle with beta = 1 (30 degrees): the new triangle on the short edge is isosceles with a
  // 30-degree apex, at distance (beta + sqrt(beta^2 - 1/4)) |pq| from the edge's midpoint.
  const Point x = deltri::off_center({0, 0}, {1, 0}, {0.5, 100}, 1.0);
  CHECK_NEAR(x.x, 0.5, 1e-15);
  CHECK_NEAR(x.y, 1 + std::sqrt(0.75), 1e-14);
}

TEST(segment_intersection_is_within_ulps_of_both_lines) {
  Random rng(43);
  int tested = 0;
  for (int i = 0; i < 6000; ++i) {
    const int kind = i % 4;
    Point a, b, c, d;
    if (kind == 0) {  // ordinary
      a = rng.point(-1, 1), b = rng.point(-1, 1), c = rng.point(-1, 1), d = rng.point(-1, 1);
    } else if (kind == 1) {  // long segments crossing near the origin
      a = rng.point(-1e9, 1e9), b = {-a.x + rng.uniform(-1, 1), -a.y + rng.uniform(-1, 1)};
      c = rng.point(-1e9, 1e9), d = {-c.x + rng.uniform(-1, 1), -c.y + rng.uniform(-1, 1)};
    } else if (kind == 2) {  // nearly parallel
      a = rng.point(-1, 1), b = rng.point(-1, 1);
      c = nudge(a, 0, rng.integer(-40, 40)), d = nudge(b, 0, rng.integer(-40, 40));
      const double t = rng.uniform(-1e-3, 1e-3);
      c = {c.x - t * (b.x - a.x), c.y - t * (b.y - a.y)};
    } else {  // far from the origin
      const Point o{1e9 + 0.25, -2e9};
      a = {o.x + rng.uniform(-1, 1), o.y + rng.uniform(-1, 1)};
      b = {o.x + rng.uniform(-1, 1), o.y + rng.uniform(-1, 1)};
      c = {o.x + rng.uniform(-1, 1), o.y + rng.uniform(-1, 1)};
      d = {o.x + rng.uniform(-1, 1), o.y + rng.uniform(-1, 1)};
    }
    // Keep proper crossings only.
    if (orient_sign(a, b, c) * orient_sign(a, b, d) >= 0) continue;
    if (orient_sign(c, d, a) * orient_sign(c, d, b) >= 0) continue;
    ++tested;
    const Point x = deltri::segment_intersection(a, b, c, d);
    CHECK(line_within_ulps(a, b, x, 2));
    CHECK(line_within_ulps(c, d, x, 2));
    CHECK(x.x >= std::min(a.x, b.x) && x.x <= std::max(a.x, b.x));
    CHECK(x.y >= std::min(c.y, d.y) && x.y <= std::max(c.y, d.y));
    const Point y = deltri::segment_intersection(c, d, a, b);
    CHECK(line_within_ulps(a, b, y, 2));
    CHECK(line_within_ulps(c, d, y, 2));
  }
  CHECK(tested > 1500);
}

TEST(segment_intersection_exact_cases) {
  const Point x = deltri::segment_intersection({0, 0}, {2, 2}, {0, 2}, {2, 0});
  CHECK_EQ(x.x, 1.0);
  CHECK_EQ(x.y, 1.0);
  const Point y = deltri::segment_intersection({-1e9, 0.1}, {1e9, 0.1}, {0.3, -5}, {0.3, 7});
  CHECK_EQ(y.x, 0.3);
  CHECK_EQ(y.y, 0.1);
}

TEST(area_and_distance) {
  CHECK_EQ(deltri::triangle_area({0, 0}, {4, 0}, {0, 3}), 6.0);
  CHECK_EQ(deltri::triangle_area({0, 0}, {0, 3}, {4, 0}), -6.0);
  CHECK_EQ(deltri::squared_distance({1, 1}, {4, 5}), 25.0);
}
