// incircle against the independent exact evaluator, on nearly and exactly cocircular inputs.
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#if defined(__GLIBC__) && (defined(__x86_64__) || defined(__i386__))
#include <fpu_control.h>
#endif

#include "geometry/exact_reference.h"
#include "geometry/predicates.h"
#include "geometry/random_support.h"
#include "harness/check.h"

namespace {

using deltri::Point;
using deltri::Predicates;
using reference::incircle_sign;
using testing_support::nudge;
using testing_support::Random;
using testing_support::sign_of;

// Four points rounded from a circle of the given centre and radius, the fourth nudged by up to two
// ulps in each coordinate; returns the number of mismatches with the exact sign.
int near_cocircular_mismatches(Predicates& pred, std::uint64_t seed, Point centre, double radius,
                               int circles) {
  Random rng(seed);
  int mismatches = 0;
  auto on_circle = [&](double angle) {
    return Point{centre.x + radius * std::cos(angle), centre.y + radius * std::sin(angle)};
  };
  for (int i = 0; i < circles; ++i) {
    const Point a = on_circle(rng.uniform(0, 2)), b = on_circle(rng.uniform(2, 4));
    const Point c = on_circle(rng.uniform(4, 6.28));
    const Point d0 = on_circle(rng.uniform(0, 6.28));
    for (int dx = -2; dx <= 2; ++dx) {
      for (int dy = -2; dy <= 2; ++dy) {
        const Point d = nudge(d0, dx, dy);
        if (sign_of(pred.incircle(a, b, c, d)) != incircle_sign(a, b, c, d)) ++mismatches;
      }
    }
  }
  return mismatches;
}

// Lattice points on x^2 + y^2 = 65^2 (many Pythagorean representations).
std::vector<std::array<int, 2>> lattice_circle() {
  std::vector<std::array<int, 2>> points;
  for (int x = -65; x <= 65; ++x) {
    for (int y = -65; y <= 65; ++y) {
      if (x * x + y * y == 65 * 65) points.push_back({x, y});
    }
  }
  return points;
}

int parity(const std::array<int, 4>& perm) {
  int inversions = 0;
  for (int i = 0; i < 4; ++i) {
    for (int j = i + 1; j < 4; ++j) inversions += perm[i] > perm[j];
  }
  return inversions % 2 ? -1 : 1;
}

}  // namespace

TEST(incircle_random_points_match_exact_sign) {
  Predicates pred;
  Random rng(20);
  for (int i = 0; i < 20000; ++i) {
    const Point a = rng.point(-1, 1), b = rng.point(-1, 1), c = rng.point(-1, 1), d = rng.point(-1, 1);
    CHECK_EQ(sign_of(pred.incircle(a, b, c, d)), incircle_sign(a, b, c, d));
  }
}

TEST(incircle_ulps_off_a_circle) {
  Predicates pred;
  CHECK_EQ(near_cocircular_mismatches(pred, 21, {0.0, 0.0}, 1.0, 1000), 0);
  CHECK_EQ(near_cocircular_mismatches(pred, 22, {0.3, -0.2}, 0.01, 1000), 0);
  CHECK(pred.counters.incircle_adaptive > 0);
}

#if defined(__GLIBC__) && (defined(__x86_64__) || defined(__i386__))
// With the x87 precision control lowered to 53 bits (as foreign code in a library's process may
// do, and as valgrind runs x87 arithmetic), long double rounds like double: the incircle filter's
// long double stage must not trust its 64-bit bound then. It did, and gave wrong signs here (under
// valgrind, data/water.poly's refinement flipped edges forever).
TEST(incircle_with_the_x87_precision_lowered) {
  fpu_control_t saved;
  _FPU_GETCW(saved);
  const fpu_control_t lowered = (saved & ~_FPU_EXTENDED) | _FPU_DOUBLE;
  _FPU_SETCW(lowered);
  Predicates pred;
  const int near = near_cocircular_mismatches(pred, 31, {0.0, 0.0}, 1.0, 1000) +
                   near_cocircular_mismatches(pred, 32, {0.3, -0.2}, 0.01, 1000) +
                   near_cocircular_mismatches(pred, 33, {1e9 + 0.3, 1e9 - 0.7}, 1.0, 500);
  _FPU_SETCW(saved);
  CHECK_EQ(near, 0);
}
#endif

TEST(incircle_huge_tiny_and_offset_circles) {
  Predicates pred;
  CHECK_EQ(near_cocircular_mismatches(pred, 23, {0.0, 0.0}, 1e60, 300), 0);
  CHECK_EQ(near_cocircular_mismatches(pred, 24, {3e60, -1e60}, 1e59, 300), 0);
  CHECK_EQ(near_cocircular_mismatches(pred, 25, {0.0, 0.0}, 1e-50, 300), 0);
  CHECK_EQ(near_cocircular_mismatches(pred, 26, {1e9 + 0.3, 1e9 - 0.7}, 1.0, 500), 0);
  CHECK_EQ(near_cocircular_mismatches(pred, 27, {-1e9, 2e9}, 1e-3, 500), 0);
}

TEST(incircle_symmetric_points_mixed_magnitudes_reach_exact_stage) {
  // (+-x, +-y) and (+-y, +-x) are exactly cocircular about the origin for any doubles x, y; with x
  // and y of very different magnitudes the differences are inexact.
  Predicates pred;
  Random rng(31);
  for (int i = 0; i < 3000; ++i) {
    const double x = rng.uniform(0.5, 1) * std::pow(10.0, rng.integer(3, 9));
    const double y = rng.uniform(-1, 1) * std::pow(10.0, rng.integer(-5, 1));
    const Point sym[8] = {{x, y}, {-y, x}, {-x, -y}, {y, -x}, {y, x}, {-x, y}, {-y, -x}, {x, -y}};
    auto pick = [&]() { return sym[rng.integer(0, 7)]; };
    const Point a = pick(), b = pick(), c = pick(), d = pick();
    CHECK_EQ(incircle_sign(a, b, c, d), 0);
    CHECK_EQ(pred.incircle(a, b, c, d), 0.0);
    const Point d1 = nudge(d, rng.integer(-1, 1), rng.integer(-1, 1));
    CHECK_EQ(sign_of(pred.incircle(a, b, c, d1)), incircle_sign(a, b, c, d1));
  }
  CHECK(pred.counters.incircle_exact > 500);
}

TEST(incircle_exactly_cocircular_lattice_points_are_zero) {
  Predicates pred;
  Random rng(28);
  const auto points = lattice_circle();
  REQUIRE(points.size() >= 12);
  // Offsets and scales chosen so that every coordinate below is exactly representable.
  const double offsets[] = {0.0, 1e9, -1e9 + 0.5, 0x1p-20};
  const int min_exp[] = {-30, -20, -20, -20}, max_exp[] = {30, 10, 10, 20};
  for (int i = 0; i < 4000; ++i) {
    const double scale = std::ldexp(1.0, rng.integer(min_exp[i % 4], max_exp[i % 4]));
    const double offset = offsets[i % 4];
    auto pick = [&]() {
      const auto& p = points[rng.integer(0, static_cast<int>(points.size()) - 1)];
      return Point{offset + scale * p[0], offset + scale * p[1]};
    };
    const Point a = pick(), b = pick(), c = pick(), d = pick();
    CHECK_EQ(incircle_sign(a, b, c, d), 0);
    CHECK_EQ(pred.incircle(a, b, c, d), 0.0);
  }
}

// Lattice points just off the circle: exact differences and a determinant that is small but not zero,
// at scales inside and outside the range where the adaptive stage's shortcut for exact zeros applies.
TEST(incircle_lattice_points_next_to_the_circle_are_not_zero) {
  Predicates pred;
  Random rng(30);
  const auto points = lattice_circle();
  std::vector<std::array<int, 2>> near;  // x^2 + y^2 = 65^2 +- 1, +- 2
  for (int x = -66; x <= 66; ++x)
    for (int y = -66; y <= 66; ++y)
      if (const int off = x * x + y * y - 65 * 65; off != 0 && off >= -2 && off <= 2) near.push_back({x, y});
  REQUIRE(!near.empty());
  const int exponents[] = {-300, -280, -250, -210, -199, -60, 0, 40, 199, 201};
  for (int i = 0; i < 4000; ++i) {
    const double scale = std::ldexp(1.0, exponents[i % 10]);
    auto at = [&](const std::array<int, 2>& p) { return Point{scale * p[0], scale * p[1]}; };
    const Point a = at(points[rng.integer(0, static_cast<int>(points.size()) - 1)]);
    const Point b = at(points[rng.integer(0, static_cast<int>(points.size()) - 1)]);
    const Point c = at(points[rng.integer(0, static_cast<int>(points.size()) - 1)]);
    const Point d = at(near[rng.integer(0, static_cast<int>(near.size()) - 1)]);
    CHECK_EQ(sign_of(pred.incircle(a, b, c, d)), incircle_sign(a, b, c, d));
  }
}

TEST(incircle_permutations_follow_parity) {
  Predicates pred;
  Random rng(29);
  for (int i = 0; i < 1500; ++i) {
    const Point centre{1e9 * (i % 2), 0.5};
    auto on_circle = [&]() {
      const double angle = rng.uniform(0, 6.28);
      return nudge(Point{centre.x + std::cos(angle), centre.y + std::sin(angle)}, rng.integer(-1, 1),
                   rng.integer(-1, 1));
    };
    const std::array<Point, 4> p = {on_circle(), on_circle(), on_circle(), on_circle()};
    const int s = sign_of(pred.incircle(p[0], p[1], p[2], p[3]));
    CHECK_EQ(s, incircle_sign(p[0], p[1], p[2], p[3]));
    std::array<int, 4> perm = {0, 1, 2, 3};
    while (std::next_permutation(perm.begin(), perm.end())) {
      CHECK_EQ(sign_of(pred.incircle(p[perm[0]], p[perm[1]], p[perm[2]], p[perm[3]])), parity(perm) * s);
    }
  }
}

TEST(incircle_counters) {
  Predicates pred;
  CHECK(pred.incircle({0, 0}, {1, 0}, {0, 1}, {0.2, 0.2}) > 0.0);
  CHECK_EQ(pred.counters.incircle_calls, 1u);
  CHECK_EQ(pred.counters.incircle_adaptive, 0u);
  // Cocircular with exact differences: decided by stage B.
  CHECK_EQ(pred.incircle({1, 0}, {0, 1}, {-1, 0}, {0, -1}), 0.0);
  CHECK_EQ(pred.counters.incircle_adaptive, 1u);
  CHECK_EQ(pred.counters.incircle_exact, 0u);
  // Quarter turns of one point about the origin are exactly cocircular, and mixing magnitudes
  // 1e9 and 0.1 makes the differences inexact, so only the exact stage can prove zero.
  const double x = 1e9, y = 0.1;
  const Point a{x, y}, b{-y, x}, c{-x, -y}, d{y, -x};
  CHECK_EQ(incircle_sign(a, b, c, d), 0);
  CHECK_EQ(pred.incircle(a, b, c, d), 0.0);
  CHECK_EQ(pred.counters.incircle_adaptive, 2u);
  CHECK_EQ(pred.counters.incircle_exact, 1u);
}

// Points of dyadic grids: the differences then span few bits and stage B is evaluated in plain
// doubles. Cocircular lattice points scaled to widths around the 12-bit limit of that shortcut,
// and the same with the fourth point one grid unit off, must all match the exact sign.
TEST(incircle_dyadic_grid_points_match_exact_sign) {
  Predicates pred;
  Random rng(32);
  const auto points = lattice_circle();
  for (int i = 0; i < 20000; ++i) {
    const int scale = rng.integer(1, 250);  // the circle's span: 130 to 32,500 units
    const double unit = std::ldexp(1.0, rng.integer(-40, 10));
    const double base = unit * rng.integer(-1000, 1000) * 65536;
    auto pick = [&]() {
      const auto& p = points[rng.integer(0, static_cast<int>(points.size()) - 1)];
      return Point{base + unit * scale * p[0], base + unit * scale * p[1]};
    };
    const Point a = pick(), b = pick(), c = pick(), d0 = pick();
    const Point d{d0.x + unit * rng.integer(-1, 1), d0.y + unit * rng.integer(-1, 1)};
    CHECK_EQ(sign_of(pred.incircle(a, b, c, d)), incircle_sign(a, b, c, d));
  }
}

// Rectangle corners about the origin are exactly cocircular, and all their differences (0, 2x,
// 2y) are exact: with x and y of full 53-bit mantissas up to nine octaves apart the differences
// span 53 to 62 bits, beyond the grid path and (exact zero) beyond the double-word stage, which
// leaves it to the integer evaluation. One ulp off, the double-word stage decides.
TEST(incircle_wide_exactly_cocircular_rectangles) {
  Predicates pred;
  Random rng(33);
  for (int i = 0; i < 5000; ++i) {
    const double x = rng.uniform(1, 2) * std::ldexp(1.0, rng.integer(-30, 30));
    const double y = x * rng.uniform(1, 2) * std::ldexp(1.0, -rng.integer(0, 9));
    std::array<Point, 4> corner = {Point{x, y}, Point{-x, y}, Point{-x, -y}, Point{x, -y}};
    for (int k = 3; k > 0; --k) std::swap(corner[k], corner[rng.integer(0, k)]);
    const Point &a = corner[0], &b = corner[1], &c = corner[2], &d = corner[3];
    CHECK_EQ(pred.incircle(a, b, c, d), 0.0);
    const Point d1 = nudge(d, rng.integer(-1, 1), rng.integer(-1, 1));
    CHECK_EQ(sign_of(pred.incircle(a, b, c, d1)), incircle_sign(a, b, c, d1));
  }
}

// Corners of axis-parallel rectangles with sides that are not dyadic (a thin strip's cells): the
// lifts x^2 + y^2 of a 2 x 2 grid are coplanar, so every order of the four is exactly zero, as the
// reference says; one corner moved by an ulp in either coordinate gives the reference's sign.
TEST(incircle_rectangle_corners_are_zero_and_their_neighbours_are_not) {
  Predicates pred;
  Random rng(31);
  for (int i = 0; i < 2000; ++i) {
    const double x0 = rng.uniform(-1, 1), y0 = rng.uniform(-1, 1) * 1e-3;
    const double x1 = x0 + rng.uniform(1e-9, 1e-6), y1 = y0 + (i % 2 ? 1e-6 : rng.uniform(1e-12, 1e3));
    const Point p[4] = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
    std::array<int, 4> perm{0, 1, 2, 3};
    do {
      const Point &a = p[perm[0]], &b = p[perm[1]], &c = p[perm[2]], &d = p[perm[3]];
      CHECK_EQ(incircle_sign(a, b, c, d), 0);
      CHECK_EQ(pred.incircle(a, b, c, d), 0.0);
    } while (std::next_permutation(perm.begin(), perm.end()));
    for (int dx = -1; dx <= 1; ++dx) {
      for (int dy = -1; dy <= 1; ++dy) {
        const Point moved = nudge(p[i % 4], dx, dy);
        const Point q[4] = {i % 4 == 0 ? moved : p[0], i % 4 == 1 ? moved : p[1], i % 4 == 2 ? moved : p[2],
                            i % 4 == 3 ? moved : p[3]};
        CHECK_EQ(sign_of(pred.incircle(q[0], q[1], q[2], q[3])), incircle_sign(q[0], q[1], q[2], q[3]));
      }
    }
  }
}
