// Constructions (geometry/constructions.h), exactly what the program calls: circumcenter (the
// Voronoi vertices), off_center (every Steiner point of refinement, its circumcentre included),
// segment_intersection (crossing segments). The references are exact dyadic rationals
// (exact_reference.h), which share no code with the functions under test.
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "geometry/constructions.h"
#include "geometry/exact_reference.h"
#include "geometry/mesh_bounds.h"
#include "geometry/random_support.h"
#include "harness/check.h"

namespace {

using deltri::Point;
using reference::orient_sign;
using testing_support::nudge;
using testing_support::Random;

double distance(const Point& a, const Point& b) { return std::sqrt(deltri::squared_distance(a, b)); }

constexpr long double kEps = 0x1p-53L;
constexpr long double kPiL = 3.141592653589793238462643383279502884L;

using reference::Dyadic;

// The exact circumcentre of abc, a + (nx, ny) / d with d = 2 (b - a) x (c - a), and the a-priori
// bound on the error of its evaluation in doubles (as a + n / d, the differences, squares and
// cross product each rounded): 8 eps times the numerators' and the denominator's condition, and
// 2 eps of the result.
struct ExactCentre {
  Point a;
  Dyadic nx{0.0}, ny{0.0}, d{0.0};
  long double tolerance = 0.0;
  long double x() const { return a.x + quotient(nx); }
  long double y() const { return a.y + quotient(ny); }
  long double quotient(const Dyadic& n) const { return static_cast<long double>(n.approximate()) / d.approximate(); }
};

ExactCentre exact_centre(const Point& a, const Point& b, const Point& c) {
  ExactCentre e;
  e.a = a;
  const Dyadic bx = Dyadic(b.x) - Dyadic(a.x), by = Dyadic(b.y) - Dyadic(a.y);
  const Dyadic cx = Dyadic(c.x) - Dyadic(a.x), cy = Dyadic(c.y) - Dyadic(a.y);
  const Dyadic b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
  e.nx = cy * b2 - by * c2;
  e.ny = bx * c2 - cx * b2;
  e.d = (bx * cy - by * cx) * Dyadic(2.0);
  const long double fbx = b.x - a.x, fby = b.y - a.y, fcx = c.x - a.x, fcy = c.y - a.y;
  const long double fb2 = fbx * fbx + fby * fby, fc2 = fcx * fcx + fcy * fcy;
  const long double d = std::fabs(static_cast<long double>(e.d.approximate()));
  const long double qx = std::fabs(e.nx.approximate() / d), qy = std::fabs(e.ny.approximate() / d);
  const long double cond_d = 2 * (std::fabs(fbx * fcy) + std::fabs(fby * fcx)) / d;
  const long double numerators = std::max(std::fabs(fcy) * fb2 + std::fabs(fby) * fc2, std::fabs(fbx) * fc2 + std::fabs(fcx) * fb2);
  const long double magnitude = std::max(std::fabs(e.x()), std::fabs(e.y()));
  e.tolerance = 8 * kEps * (numerators / d + std::max(qx, qy) * cond_d) + 2 * kEps * magnitude;
  return e;
}

// Whether o is within e's bound of the exact centre, the error computed exactly: for x,
// ((o.x - a.x) d - nx) / d.
bool within_bound(const Point& o, const ExactCentre& e) {
  const double d = e.d.approximate();
  const double ex = ((Dyadic(o.x) - Dyadic(e.a.x)) * e.d - e.nx).approximate() / d;
  const double ey = ((Dyadic(o.y) - Dyadic(e.a.y)) * e.d - e.ny).approximate() / d;
  return std::fabs(ex) <= e.tolerance && std::fabs(ey) <= e.tolerance;
}

struct Triangle {
  Point a, b, c;
};

// Triangles of five kinds: in the unit square, far from the origin, tiny, large, and on an integer
// grid (exact differences, cocircular ties likely).
Triangle random_triangle(Random& rng, int i) {
  const struct {
    double offset, size;
  } kinds[] = {{0.0, 1.0}, {1e9, 1.0}, {-3e5, 1e-3}, {0.0, 1e6}};
  if (i % 5 == 4) {
    const auto grid = [&] { return Point{double(rng.integer(-1000, 1000)), double(rng.integer(-1000, 1000))}; };
    return {grid(), grid(), grid()};
  }
  const double offset = kinds[i % 5].offset, size = kinds[i % 5].size;
  const auto at = [&] { return Point{offset + size * rng.uniform(-1, 1), offset + size * rng.uniform(-1, 1)}; };
  return {at(), at(), at()};
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

TEST(circumcenter_matches_the_exact_centre) {
  Random rng(40);
  for (int i = 0; i < 12000; ++i) {
    const Triangle t = random_triangle(rng, i);
    if (orient_sign(t.a, t.b, t.c) == 0) continue;
    const ExactCentre e = exact_centre(t.a, t.b, t.c);
    CHECK(within_bound(deltri::circumcenter(t.a, t.b, t.c), e));
    CHECK(within_bound(deltri::circumcenter(t.b, t.c, t.a), exact_centre(t.b, t.c, t.a)));
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

// The Steiner point refinement computes (its circumcentre when factor is 0), for the factors the
// angle bounds give, on random triangles and needles: within the a-priori bound of the exact
// circumcentre, or of the exact off-centre (the point at height factor |pq| on the way from pq's
// midpoint to the exact circumcentre) when that is nearer pq. Where the two distances are too
// close to call in doubles, either point may come out.
// depth_in_circumcircle is a lower bound: every point q at that distance from p is strictly inside
// the circle, decided by the exact incircle sign. p is placed at a random fraction of the way to
// the circle, up to a few ulps from it, so that the bound's slack is what keeps q inside; the
// triangles include the five kinds above and needles whose apex is a few ulps off the base
// line, where the centre's rounding is largest. A bound without its slack fails here.
TEST(depth_in_circumcircle_is_a_lower_bound) {
  CHECK(reference::incircle_sign({0, 0}, {1, 0}, {0, 1}, {0.2, 0.2}) > 0);  // the sign's sense
  Random rng(45);
  int positive = 0;
  for (int i = 0; i < 20000; ++i) {
    Triangle t = random_triangle(rng, i);
    if (i % 3 == 0) {
      const Point mid{(t.a.x + t.b.x) / 2, (t.a.y + t.b.y) / 2};
      t.c = nudge(mid, rng.integer(-64, 64), rng.integer(-64, 64));
    }
    const int turn = orient_sign(t.a, t.b, t.c);
    if (turn == 0) continue;
    if (turn < 0) std::swap(t.b, t.c);
    const Point o = deltri::circumcenter(t.a, t.b, t.c);
    const double r = distance(o, t.a);
    const double angle = rng.uniform(0.0, 2.0 * std::numbers::pi);
    const double fraction = i % 2 == 0 ? rng.uniform(0.0, 1.0) : 1.0 - std::ldexp(1.0, -rng.integer(8, 50));
    const Point p{o.x + fraction * r * std::cos(angle), o.y + fraction * r * std::sin(angle)};
    const double depth = deltri::depth_in_circumcircle(t.a, t.b, t.c, p);
    if (!(depth > 0.0)) continue;
    ++positive;
    for (int k = 0; k < 8; ++k) {
      const double phi = k * std::numbers::pi / 4.0;
      const Point q{p.x + depth * std::cos(phi), p.y + depth * std::sin(phi)};
      CHECK(reference::incircle_sign(t.a, t.b, t.c, q) > 0);
    }
  }
  CHECK(positive > 5000);
}

TEST(depth_in_circumcircle_exact_cases) {
  // The circle through (0,0), (2,0), (0,2): centre (1,1), radius sqrt 2.
  CHECK_NEAR(deltri::depth_in_circumcircle({0, 0}, {2, 0}, {0, 2}, {1, 1}), std::sqrt(2.0), 1e-12);
  CHECK_NEAR(deltri::depth_in_circumcircle({0, 0}, {2, 0}, {0, 2}, {1, 0}), std::sqrt(2.0) - 1.0, 1e-12);
  CHECK(deltri::depth_in_circumcircle({0, 0}, {2, 0}, {0, 2}, {3, 3}) < 0.0);
  CHECK(deltri::depth_in_circumcircle({0, 0}, {2, 0}, {0, 2}, {0, 0}) <= 0.0);  // on the circle
  CHECK(deltri::depth_in_circumcircle({0, 0}, {1, 0}, {2, 0}, {1, 0}) == -HUGE_VAL);  // flat
}

TEST(off_center_matches_the_exact_construction) {
  Random rng(42);
  const double thetas[] = {10.0, 20.0, 25.0, 30.0, 33.0, 34.0, 40.0};
  int off_centres = 0, circumcentres = 0;
  for (int i = 0; i < 14000; ++i) {
    const double factor = deltri::AngleBound(thetas[i % 7]).off_center_factor();
    Triangle t = random_triangle(rng, i);
    if (i % 3 == 0) t.b = {t.a.x + 0.01 * (t.b.x - t.a.x), t.a.y + 0.01 * (t.b.y - t.a.y)};  // a needle
    if (orient_sign(t.a, t.b, t.c) == 0) continue;
    // pq the shortest edge, pqr counter-clockwise, as the Terminator passes them.
    Point p = t.a, q = t.b, r = t.c;
    if (deltri::squared_distance(q, r) < deltri::squared_distance(p, q)) p = t.b, q = t.c, r = t.a;
    if (deltri::squared_distance(t.c, t.a) < deltri::squared_distance(p, q)) p = t.c, q = t.a, r = t.b;
    if (orient_sign(p, q, r) < 0) std::swap(p, q);
    const ExactCentre e = exact_centre(p, q, r);
    const Point centre = deltri::off_center(p, q, r, 0.0);
    CHECK(within_bound(centre, e));
    const Point x = deltri::off_center(p, q, r, factor);
    // The exact off-centre, from the exact centre (long double is ample for a reference point).
    const long double mx = 0.5L * p.x + 0.5L * q.x, my = 0.5L * p.y + 0.5L * q.y;
    // a - m is exact in long double; only the small quotient rounds.
    const long double dx = (p.x - mx) + e.quotient(e.nx), dy = (p.y - my) + e.quotient(e.ny);
    const long double d = std::sqrt(dx * dx + dy * dy);
    const long double pq = std::sqrt(static_cast<long double>(deltri::squared_distance(p, q)));
    const long double h = factor * pq;
    const long double slack = e.tolerance + 1e-9L * d;
    if (std::fabs(h - d) <= slack) continue;
    if (h > d) {
      ++circumcentres;
      CHECK(x == centre);
      continue;
    }
    ++off_centres;
    const long double ox = mx + h / d * dx, oy = my + h / d * dy;
    const long double tolerance = e.tolerance + 8 * kEps * (std::fabs(mx) + std::fabs(my) + h);
    CHECK(std::fabs(x.x - ox) <= tolerance && std::fabs(x.y - oy) <= tolerance);
    // The new triangle on pq has its apex angle 2 atan(1 / (2 factor)), a little above theta.
    const long double hx = 0.5L * (p.x - q.x), hy = 0.5L * (p.y - q.y);  // p - m, exactly
    const long double ux = hx - h / d * dx, uy = hy - h / d * dy, vx = -hx - h / d * dx, vy = -hy - h / d * dy;
    const long double apex = std::atan2(std::fabs(ux * vy - uy * vx), ux * vx + uy * vy) * 180 / kPiL;
    CHECK(std::fabs(apex - 2 * std::atan(0.5L / factor) * 180 / kPiL) < 1e-6L);
    CHECK(apex > thetas[i % 7]);
  }
  CHECK(off_centres > 1000);
  CHECK(circumcentres > 1000);
}

TEST(off_center_exact_cases) {
  // A needle with a 10 degree apex over the base from (-1, 0) to (1, 0), theta 30: the off-centre
  // at height 0.475 cot(15 degrees) |pq| = 3.5454 on the bisector, below the circumcentre (5.67).
  const double h = 1.0 / std::tan(5 * kPiL / 180);
  const double factor = deltri::AngleBound(30.0).off_center_factor();
  CHECK_NEAR(factor, 0.475 / std::tan(15 * kPiL / 180), 1e-15);
  const Point x = deltri::off_center({-1, 0}, {1, 0}, {0, h}, factor);
  CHECK_EQ(x.x, 0.0);
  CHECK_NEAR(x.y, 2 * factor, 1e-14);
  CHECK(deltri::off_center({-1, 0}, {1, 0}, {0, h}, 0.0) == deltri::circumcenter({-1, 0}, {1, 0}, {0, h}));
  // A good triangle keeps its circumcentre; no angle bound (factor 0) always does.
  const Point centre = deltri::off_center({0, 0}, {2, 0}, {1, 1.6}, factor);
  CHECK(centre == deltri::off_center({0, 0}, {2, 0}, {1, 1.6}, 0.0));
  CHECK_EQ(deltri::AngleBound().off_center_factor(), 0.0);
  CHECK_EQ(deltri::AngleBound(0.0).off_center_factor(), 0.0);
  const Point o = deltri::off_center({0, 0}, {2, 0}, {0, 2}, 0.0);
  CHECK_EQ(o.x, 1.0);
  CHECK_EQ(o.y, 1.0);
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
