// Diametral circle (exact) and diametral lens encroachment tests.
#include <cmath>

#include "geometry/encroachment.h"
#include "geometry/exact_reference.h"
#include "geometry/random_support.h"
#include "harness/check.h"

namespace {

using deltri::in_diametral_circle;
using deltri::in_diametral_lens;
using deltri::Point;
using reference::dot_sign;
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

// The angle apb in degrees, accurate near 0 and 180.
double angle_degrees(const Point& a, const Point& b, const Point& p) {
  const double ux = a.x - p.x, uy = a.y - p.y, vx = b.x - p.x, vy = b.y - p.y;
  return std::atan2(std::fabs(ux * vy - uy * vx), ux * vx + uy * vy) * 180 / kPi;
}

}  // namespace

TEST(diametral_circle_matches_exact_dot_product) {
  Random rng(50);
  const double offsets[] = {0.0, 1e9 + 0.5, -1e-3};
  const double sizes[] = {1.0, 1e-6, 1e6};
  int inside = 0, outside = 0;
  for (int i = 0; i < 1500; ++i) {
    const double offset = offsets[i % 3], size = sizes[(i / 3) % 3];
    const Point a{offset + size * rng.uniform(-1, 1), offset + size * rng.uniform(-1, 1)};
    const Point b{offset + size * rng.uniform(-1, 1), offset + size * rng.uniform(-1, 1)};
    near_circle_points(rng, a, b, 10, [&](const Point& p) {
      const bool expected = dot_sign(a, b, p) < 0;
      CHECK_EQ(in_diametral_circle(a, b, p), expected);
      CHECK_EQ(in_diametral_circle(b, a, p), expected);
      CHECK_EQ(in_diametral_lens(a, b, p, 45.0), expected);
      (expected ? inside : outside)++;
    });
    const Point q{offset + size * rng.uniform(-2, 2), offset + size * rng.uniform(-2, 2)};
    CHECK_EQ(in_diametral_circle(a, b, q), dot_sign(a, b, q) < 0);
  }
  CHECK(inside > 1000);
  CHECK(outside > 1000);
}

TEST(diametral_circle_exact_boundary_cases) {
  // Thales: (4, 0) and (0, 2) see the diameter from (0, 0) to (4, 2) at exactly 90 degrees.
  const Point a{0, 0}, b{4, 2};
  CHECK(!in_diametral_circle(a, b, {4, 0}));
  CHECK(!in_diametral_circle(a, b, {0, 2}));
  CHECK(in_diametral_circle(a, b, {nudge(4.0, -1), nudge(0.0, 1)}));
  CHECK(!in_diametral_circle(a, b, a));
  CHECK(!in_diametral_circle(a, b, b));
  CHECK(in_diametral_circle(a, b, {2, 1}));
  CHECK(!in_diametral_circle(a, a, {2, 1}));
  // Far from the origin, the same configuration with inexact differences.
  const double o = 1e9 + 0.1, t = 0.3;
  CHECK_EQ(in_diametral_circle({o, t}, {-t, o}, {t, -o}), dot_sign({o, t}, {-t, o}, {t, -o}) < 0);
}

TEST(diametral_lens_angle_threshold) {
  Random rng(51);
  const double thetas[] = {30.0, 20.0, 40.0, 60.0, 10.0};
  for (int i = 0; i < 20000; ++i) {
    const double theta = thetas[i % 5];
    const Point a = rng.point(-1, 1), b = rng.point(-1, 1), p = rng.point(-1.5, 1.5);
    const double angle = angle_degrees(a, b, p);
    const double threshold = 180 - 2 * theta;
    const bool in_lens = in_diametral_lens(a, b, p, theta);
    if (angle > threshold + 1e-7) CHECK(in_lens);
    if (angle < threshold - 1e-7) CHECK(!in_lens);
    CHECK_EQ(in_lens, in_diametral_lens(b, a, p, theta));
    // Narrow lenses lie inside the diametral circle, wide ones contain it.
    if (theta < 45 && in_lens) CHECK(in_diametral_circle(a, b, p));
    if (theta > 45 && in_diametral_circle(a, b, p)) CHECK(in_lens);
  }
}

TEST(diametral_lens_edge_cases) {
  const Point a{0, 0}, b{2, 0};
  CHECK(!in_diametral_lens(a, b, {1, 0.1}, 0.0));
  CHECK(!in_diametral_lens(a, b, {1, 0.0}, -5.0));
  CHECK(in_diametral_lens(a, b, {1, 0.0}, 30.0));
  CHECK(in_diametral_lens(a, b, {0.5, 0.0}, 1.0));
  CHECK(!in_diametral_lens(a, b, a, 30.0));
  CHECK(!in_diametral_lens(a, b, b, 60.0));
  CHECK(!in_diametral_lens(a, b, {3, 0}, 90.0));
  CHECK(!in_diametral_lens(a, b, {3, 0}, 120.0));
  CHECK(in_diametral_lens(a, b, {3, 0.001}, 90.0));
  // For 30 degrees the lens apex on the bisector is at height tan(30) = 1/sqrt(3) above the midpoint.
  CHECK(in_diametral_lens(a, b, {1, 0.577}, 30.0));
  CHECK(!in_diametral_lens(a, b, {1, 0.578}, 30.0));
  CHECK(in_diametral_lens(a, b, {1, -0.577}, 30.0));
  CHECK(in_diametral_circle(a, b, {1, 0.578}));
}
