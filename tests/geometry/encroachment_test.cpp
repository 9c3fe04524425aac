// Encroachment (geometry/encroachment.h), exactly what refinement calls: diametral_dot_sign,
// strictly_inside_diametral_circle (Chew's step) and encroaches with the circle and lens rules
// (every encroachment test of the Terminator). The references are exact and share no code with the functions under
// test: dyadic rationals (exact_reference.h) for any doubles, 128-bit integers for integer inputs.
#include <cmath>
#include <cstdint>
#include <random>

#include "geometry/encroachment.h"
#include "geometry/exact_reference.h"
#include "geometry/mesh_bounds.h"
#include "geometry/random_support.h"
#include "harness/check.h"

namespace {

using deltri::diametral_dot_sign;
using deltri::EncroachRule;
using deltri::encroaches;
using deltri::strictly_inside_diametral_circle;
using deltri::Point;
using deltri::Predicates;
using testing_support::nudge;
using testing_support::Random;

constexpr double kPi = 3.14159265358979323846;

// Points on or within two ulps of the diametral circle of ab.
template <class Visit>
void near_circle_points(Random& rng, const Point& a, const Point& b, int count, Visit visit) {
  const Point mid{(a.x + b.x) / 2, (a.y + b.y) / 2};
  const double radius = std::hypot(b.x - a.x, b.y - a.y) / 2;
  for (int i = 0; i < count; ++i) {
    const double angle = rng.uniform(0, 2 * kPi);
    const Point on{mid.x + radius * std::cos(angle), mid.y + radius * std::sin(angle)};
    visit(nudge(on, rng.integer(-2, 2), rng.integer(-2, 2)));
  }
}

Point point_of(std::int64_t x, std::int64_t y) { return {static_cast<double>(x), static_cast<double>(y)}; }

// The exact values the lens reference needs, for integer points (|coordinates| < 2^40).
struct ExactAngle {
  __int128 dot, cross, pa2, pb2;
};

ExactAngle exact_angle(std::int64_t ax, std::int64_t ay, std::int64_t bx, std::int64_t by, std::int64_t px,
                       std::int64_t py) {
  const __int128 ux = ax - px, uy = ay - py, vx = bx - px, vy = by - py;
  return {ux * vx + uy * vy, ux * vy - uy * vx, ux * ux + uy * uy, vx * vx + vy * vy};
}

// The angle apb in degrees from the exact dot and cross products (long double: the products are
// exact integers below 2^82, rounded once to 64 bits each).
long double angle_degrees(const ExactAngle& e) {
  return std::atan2(std::fabs(static_cast<long double>(e.cross)), static_cast<long double>(e.dot)) * 180.0L /
         3.141592653589793238462643383279502884L;
}

}  // namespace

TEST(diametral_dot_sign_matches_exact_dot_product) {
  Random rng(50);
  // Far from the origin the differences round; at the ends of the double range the products leave
  // the expansions' range and the integer path decides.
  const struct {
    double offset, size;
  } scales[] = {{0.0, 1.0}, {0.0, 1e-6}, {0.0, 1e6}, {1e9 + 0.5, 1.0}, {1e9 + 0.5, 1e-6},
                {-1e-3, 1.0}, {-1e-3, 1e-6}, {1e-200, 1e-206}, {3e150, 1e146}, {0.0, 1e-300}};
  int inside = 0, outside = 0;
  for (int i = 0; i < 3000; ++i) {
    const double offset = scales[i % 10].offset, size = scales[i % 10].size;
    const Point a{offset + size * rng.uniform(-1, 1), offset + size * rng.uniform(-1, 1)};
    const Point b{offset + size * rng.uniform(-1, 1), offset + size * rng.uniform(-1, 1)};
    near_circle_points(rng, a, b, 10, [&](const Point& p) {
      const int expected = reference::dot_sign(a, b, p);
      CHECK_EQ(diametral_dot_sign(a, b, p), expected);
      CHECK_EQ(diametral_dot_sign(b, a, p), expected);
      CHECK_EQ(strictly_inside_diametral_circle(a, b, p), expected < 0);
      if (expected != 0) (expected < 0 ? inside : outside)++;
    });
    const Point q{offset + size * rng.uniform(-2, 2), offset + size * rng.uniform(-2, 2)};
    CHECK_EQ(diametral_dot_sign(a, b, q), reference::dot_sign(a, b, q));
  }
  CHECK(inside > 1000);
  CHECK(outside > 1000);
}

// Points within two units of the diametral circle of xy, all coordinates integers below 2^51
// (exact doubles): x = c + (u, v), y = c - (u, v) and w = c + (-v, u) plus a nudge, so w is on the
// circle before the nudge (a fifth of the points stay on it). The products in (x - w).(y - w) need
// up to 104 bits, so a floating-point dot product gets about one sign in 300 wrong here; the
// reference is the same expression in 128-bit integers.
TEST(circle_rule_matches_an_integer_reference_on_and_near_the_circle) {
  Predicates pred;
  const EncroachRule circle = EncroachRule::circle();
  std::mt19937_64 rng(11);
  std::uniform_int_distribution<std::int64_t> coord(-(std::int64_t{1} << 50), std::int64_t{1} << 50);
  std::uniform_int_distribution<int> nudge_by(-2, 2);
  int inside = 0, outside = 0, on = 0;
  for (int i = 0; i < 20000; ++i) {
    const std::int64_t cx = coord(rng), cy = coord(rng), u = coord(rng), v = coord(rng);
    const std::int64_t X[2] = {cx + u, cy + v}, Y[2] = {cx - u, cy - v};
    const std::int64_t W[2] = {cx - v + nudge_by(rng), cy + u + nudge_by(rng)};
    const __int128 dot = static_cast<__int128>(X[0] - W[0]) * (Y[0] - W[0]) + static_cast<__int128>(X[1] - W[1]) * (Y[1] - W[1]);
    const Point x = point_of(X[0], X[1]), y = point_of(Y[0], Y[1]), w = point_of(W[0], W[1]);
    // On the circle counts: the one boundary rule (encroachment.h).
    CHECK_EQ(encroaches(pred, x, y, w, circle), dot <= 0);
    CHECK_EQ(strictly_inside_diametral_circle(x, y, w), dot < 0);
    CHECK_EQ(diametral_dot_sign(x, y, w), dot < 0 ? -1 : dot > 0 ? 1 : 0);
    (dot < 0 ? inside : dot > 0 ? outside : on) += 1;
  }
  CHECK(inside > 1000 && outside > 1000 && on > 500);  // both sides and the circle itself (1 in 25)
}

TEST(boundary_rule_on_exact_cases) {
  // Thales: (4, 0) and (0, 2) see the diameter from (0, 0) to (4, 2) at exactly 90 degrees.
  Predicates pred;
  const Point a{0, 0}, b{4, 2};
  for (const Point& p : {Point{4, 0}, Point{0, 2}, a, b}) {
    CHECK(encroaches(pred, a, b, p, EncroachRule::circle()));  // on the circle: encroaches
    CHECK(!strictly_inside_diametral_circle(a, b, p));         // and is not deleted by Chew's step
  }
  CHECK(!encroaches(pred, a, b, {nudge(4.0, 1), 0.0}, EncroachRule::circle()));
  CHECK(strictly_inside_diametral_circle(a, b, {nudge(4.0, -1), nudge(0.0, 1)}));
  CHECK(!strictly_inside_diametral_circle(a, b, {5, 0}));
  // A lens is bounded by arcs above 90 degrees: the circle's points and the ends are outside it,
  // the open subsegment inside, the line beyond it outside.
  const EncroachRule lens = EncroachRule::lens(30.0);
  CHECK(!encroaches(pred, a, b, {4, 0}, lens));
  CHECK(!encroaches(pred, a, b, a, lens));
  CHECK(encroaches(pred, a, b, {2, 1}, lens));
  CHECK(!encroaches(pred, a, b, {6, 3}, lens));
  // The lens of 0 degrees is the open subsegment alone.
  const EncroachRule none = EncroachRule::lens(0.0);
  CHECK(encroaches(pred, a, b, {1, 0.5}, none));
  CHECK(!encroaches(pred, a, b, {1, 0.5000001}, none));
}

TEST(lens_rule_is_made_once_from_theta) {
  const EncroachRule lens = EncroachRule::lens(30.0);
  CHECK_NEAR(lens.min_apex_angle_deg, 120.0, 1e-12);
  CHECK_NEAR(lens.cos2_apex, 0.25, 1e-15);
  CHECK_EQ(EncroachRule::lens(45.0).min_apex_angle_deg, 90.0);  // never wider than the circle
  CHECK_EQ(EncroachRule::lens(50.0).min_apex_angle_deg, 90.0);
  CHECK_EQ(EncroachRule::circle().min_apex_angle_deg, 90.0);
  CHECK_EQ(EncroachRule::lens(0.0).min_apex_angle_deg, 180.0);
}

// The lens rule against the exact angle on integer points: random triples, and points within a
// unit of a lens arc (a chord of length 2L seen at the apex angle phi from the arc of radius
// L / sin(phi) centred at L cot(phi) on the bisector). Away from the arc (more than 1e-9 degrees)
// the answer must be the exact one; nearer, the arc is irrational and either answer is allowed.
TEST(lens_rule_matches_the_exact_angle_on_integer_points) {
  Predicates pred;
  std::mt19937_64 rng(12);
  std::uniform_int_distribution<std::int64_t> coord(-(std::int64_t{1} << 24), std::int64_t{1} << 24);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double thetas[] = {0.01, 10.0, 20.0, 25.0, 30.0, 33.0, 34.0, 40.0, 44.9};
  int in = 0, out = 0, near_arc_in = 0, near_arc_out = 0, undecided = 0;
  for (int i = 0; i < 60000; ++i) {
    const double theta = thetas[i % 9];
    const EncroachRule rule = EncroachRule::lens(theta);
    const long double apex = 180.0L - 2.0L * theta;
    std::int64_t A[2], B[2], P[2];
    const bool near_arc = i % 2 == 1;
    if (!near_arc) {
      for (auto* q : {A, B, P}) q[0] = coord(rng), q[1] = coord(rng);
    } else {
      // A horizontal or vertical chord of length 2L and a point rounded from the arc on either
      // side: the arc is centred at (0, c) with c = L / tan(apex) < 0, radius L / sin(apex).
      const std::int64_t L = 1 + (coord(rng) & 0xfffff), cx = coord(rng), cy = coord(rng);
      const double phi = static_cast<double>(apex) * kPi / 180;
      const double radius = L / std::sin(phi), c = L / std::tan(phi);
      double along = 0.0, across = -1.0;
      while (!(across > 0.0)) {
        const double t = unit(rng) * kPi;
        along = radius * std::cos(t), across = c + radius * std::sin(t);
      }
      const double side = i % 4 == 1 ? 1.0 : -1.0;
      const bool vertical = i % 8 < 4;
      const std::int64_t s = std::llround(along), h = std::llround(side * across);
      A[0] = cx - (vertical ? 0 : L), A[1] = cy - (vertical ? L : 0);
      B[0] = cx + (vertical ? 0 : L), B[1] = cy + (vertical ? L : 0);
      P[0] = cx + (vertical ? h : s), P[1] = cy + (vertical ? s : h);
    }
    const ExactAngle e = exact_angle(A[0], A[1], B[0], B[1], P[0], P[1]);
    const Point a = point_of(A[0], A[1]), b = point_of(B[0], B[1]), p = point_of(P[0], P[1]);
    const bool got = encroaches(pred, a, b, p, rule);
    CHECK_EQ(encroaches(pred, b, a, p, rule), got);
    bool expected;
    if (e.pa2 == 0 || e.pb2 == 0) {
      expected = false;  // p at an end: no angle, and no lens holds it
    } else if (e.cross == 0) {
      expected = e.dot < 0;  // on the line: inside the subsegment (180 degrees) or beyond it (0)
    } else {
      const long double angle = angle_degrees(e);
      if (std::fabs(angle - apex) < 1e-9L) {
        ++undecided;
        continue;
      }
      expected = angle > apex;
    }
    CHECK_EQ(got, expected);
    if (near_arc) (expected ? near_arc_in : near_arc_out)++;
    else (expected ? in : out)++;
  }
  CHECK(in > 200 && out > 10000);
  CHECK(near_arc_in > 5000 && near_arc_out > 5000);  // the arcs were tried from both sides
  CHECK(undecided < 100);
}

// The angle bound's lens, as the Terminator builds it, against the same exact angle: a point that
// sees the subsegment at exactly 180 - 2 theta is on the boundary and encroaches when the cosine
// rounds that way; one a degree inside or outside is decided by the angle.
TEST(lens_from_the_angle_bound) {
  Predicates pred;
  const deltri::AngleBound bound(30.0);
  const EncroachRule rule = EncroachRule::lens(bound.degrees());
  const Point a{-1, 0}, b{1, 0};
  for (double apex : {119.0, 121.0}) {
    const double h = 1.0 / std::tan(apex / 2 * kPi / 180);
    CHECK_EQ(encroaches(pred, a, b, {0, h}, rule), apex > 120);
    CHECK_EQ(encroaches(pred, a, b, {0, -h}, rule), apex > 120);
  }
}
