// orient2d against the independent exact evaluator, on inputs built to defeat the filter.
#include <cmath>

#include "geometry/exact_reference.h"
#include "geometry/predicates.h"
#include "geometry/random_support.h"
#include "harness/check.h"

namespace {

using deltri::Point;
using deltri::Predicates;
using reference::orient_sign;
using testing_support::nudge;
using testing_support::Random;
using testing_support::sign_of;

// Points on or within a few ulps of lines through random a, b in the square [lo, hi]^2 (shifted by
// offset); returns the number of mismatches with the exact sign.
int near_collinear_mismatches(Predicates& pred, std::uint64_t seed, double lo, double hi,
                              double offset, int lines) {
  Random rng(seed);
  int mismatches = 0;
  for (int i = 0; i < lines; ++i) {
    const Point a{offset + rng.uniform(lo, hi), offset + rng.uniform(lo, hi)};
    const Point b{offset + rng.uniform(lo, hi), offset + rng.uniform(lo, hi)};
    const double t = rng.uniform(-2.0, 3.0);
    const Point on_line{a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};
    for (int dx = -2; dx <= 2; ++dx) {
      for (int dy = -2; dy <= 2; ++dy) {
        const Point c = nudge(on_line, dx, dy);
        if (sign_of(pred.orient2d(a, b, c)) != orient_sign(a, b, c)) ++mismatches;
      }
    }
  }
  return mismatches;
}

}  // namespace

TEST(orient2d_random_points_match_exact_sign) {
  Predicates pred;
  Random rng(10);
  for (int i = 0; i < 20000; ++i) {
    const Point a = rng.point(-1, 1), b = rng.point(-1, 1), c = rng.point(-1, 1);
    CHECK_EQ(sign_of(pred.orient2d(a, b, c)), orient_sign(a, b, c));
  }
}

TEST(orient2d_points_ulps_off_a_line) {
  Predicates pred;
  CHECK_EQ(near_collinear_mismatches(pred, 11, -1.0, 1.0, 0.0, 2000), 0);
  CHECK(pred.counters.orient_adaptive > 0);
}

TEST(orient2d_near_collinear_huge_and_tiny_magnitudes) {
  Predicates pred;
  CHECK_EQ(near_collinear_mismatches(pred, 12, -1e100, 1e100, 0.0, 1000), 0);
  CHECK_EQ(near_collinear_mismatches(pred, 13, -1e-100, 1e-100, 0.0, 1000), 0);
  CHECK_EQ(near_collinear_mismatches(pred, 14, 1e99, 1e100, 0.0, 1000), 0);
}

TEST(orient2d_near_collinear_with_large_offsets_reaches_exact_stage) {
  Predicates pred;
  CHECK_EQ(near_collinear_mismatches(pred, 15, -1.0, 1.0, 1e9, 2000), 0);
  CHECK_EQ(near_collinear_mismatches(pred, 16, -1e-3, 1e-3, 1e9 + 0.3, 2000), 0);
  CHECK_EQ(near_collinear_mismatches(pred, 17, -1e9, 1e9, 0.0, 2000), 0);
}

TEST(orient2d_exactly_collinear_mixed_magnitudes_reach_exact_stage) {
  // s * (2^i, 2^j) is exact for any double s, so such points are exactly collinear with the origin
  // while their differences, mixing magnitudes, are not exact.
  Predicates pred;
  Random rng(30);
  for (int i = 0; i < 5000; ++i) {
    const double ux = std::ldexp(rng.integer(0, 1) ? 1.0 : -1.0, rng.integer(-3, 3));
    const double uy = std::ldexp(rng.integer(0, 1) ? 1.0 : -1.0, rng.integer(-3, 3));
    auto at = [&]() {
      const double s = rng.uniform(-1, 1) * std::pow(10.0, rng.integer(-5, 9));
      return Point{s * ux, s * uy};
    };
    const Point a = at(), b = at(), c = at();
    CHECK_EQ(orient_sign(a, b, c), 0);
    CHECK_EQ(pred.orient2d(a, b, c), 0.0);
    const Point c1 = nudge(c, rng.integer(-1, 1), rng.integer(-1, 1));
    CHECK_EQ(sign_of(pred.orient2d(a, b, c1)), orient_sign(a, b, c1));
  }
  CHECK(pred.counters.orient_exact > 1000);
}

TEST(orient2d_exactly_collinear_grid_points_are_zero) {
  Predicates pred;
  Random rng(18);
  // Offsets and scales chosen so that every coordinate below is exactly representable.
  const double offsets[] = {0.0, 1e9, -7.5e8 + 0.25, 0x1p-30};
  const int min_exp[] = {-40, -20, -20, -30}, max_exp[] = {40, 10, 10, 0};
  for (int i = 0; i < 5000; ++i) {
    const double scale = std::ldexp(1.0, rng.integer(min_exp[i % 4], max_exp[i % 4]));
    const double offset = offsets[i % 4];
    const int vx = rng.integer(-50, 50), vy = rng.integer(-50, 50);
    const int ox = rng.integer(-1000, 1000), oy = rng.integer(-1000, 1000);
    auto at = [&](int k) { return Point{offset + scale * (ox + k * vx), offset + scale * (oy + k * vy)}; };
    const Point a = at(rng.integer(-20, 20)), b = at(rng.integer(-20, 20)), c = at(rng.integer(-20, 20));
    CHECK_EQ(orient_sign(a, b, c), 0);
    CHECK_EQ(pred.orient2d(a, b, c), 0.0);
  }
}

TEST(orient2d_sign_symmetries) {
  Predicates pred;
  Random rng(19);
  for (int i = 0; i < 5000; ++i) {
    const Point a{1e9 + rng.uniform(-1, 1), rng.uniform(-1, 1)};
    const Point b{1e9 + rng.uniform(-1, 1), rng.uniform(-1, 1)};
    const double t = rng.uniform(-1, 2);
    const Point c = nudge(Point{a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)}, rng.integer(-1, 1),
                          rng.integer(-1, 1));
    const int s = sign_of(pred.orient2d(a, b, c));
    CHECK_EQ(s, orient_sign(a, b, c));
    CHECK_EQ(sign_of(pred.orient2d(b, c, a)), s);
    CHECK_EQ(sign_of(pred.orient2d(c, a, b)), s);
    CHECK_EQ(sign_of(pred.orient2d(b, a, c)), -s);
    CHECK_EQ(sign_of(pred.orient2d(a, c, b)), -s);
    CHECK_EQ(sign_of(pred.orient2d(c, b, a)), -s);
  }
}

TEST(orient2d_counters) {
  Predicates pred;
  CHECK(pred.orient2d({0, 0}, {1, 0}, {0, 1}) > 0.0);
  CHECK_EQ(pred.counters.orient_calls, 1u);
  CHECK_EQ(pred.counters.orient_adaptive, 0u);
  // Exactly collinear with exact differences: the filter fails, stage B settles it.
  CHECK_EQ(pred.orient2d({0, 0}, {1, 1}, {2, 2}), 0.0);
  CHECK_EQ(pred.counters.orient_adaptive, 1u);
  CHECK_EQ(pred.counters.orient_exact, 0u);
  // Collinear points whose differences are inexact: only the exact stage can prove zero.
  const double t = 0.1;
  const Point a{1e9 + t, 1e9 + t}, b{-1e9 - 3 * t, -1e9 - 3 * t}, c{t, t};
  CHECK_EQ(orient_sign(a, b, c), 0);
  CHECK_EQ(pred.orient2d(a, b, c), 0.0);
  CHECK_EQ(pred.counters.orient_adaptive, 2u);
  CHECK_EQ(pred.counters.orient_exact, 1u);
  CHECK_EQ(pred.counters.orient_calls, 3u);
}

TEST(orient2d_degenerate_inputs) {
  Predicates pred;
  const Point p{0.1, 0.7};
  CHECK_EQ(pred.orient2d(p, p, p), 0.0);
  CHECK_EQ(pred.orient2d(p, p, {3, 4}), 0.0);
  CHECK_EQ(pred.orient2d({0, 0}, {0, 0}, {1e-300, 0}), 0.0);
}
