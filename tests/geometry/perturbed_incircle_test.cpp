// incircle_perturbed (the tie rule shared by the Delaunay builders) against the independent exact
// reference: the sign of the 4x4 lifted determinant with each lift lowered by eps^rank, expanded
// by Leibniz's formula in arbitrary precision (exact_reference.h), on inputs full of exact ties.
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "geometry/exact_reference.h"
#include "geometry/predicates.h"
#include "geometry/random_support.h"
#include "harness/check.h"

namespace {

using deltri::Point;
using deltri::Predicates;
using reference::perturbed_incircle_sign;
using testing_support::Random;
using testing_support::sign_of;

// Four distinct points drawn from `pool` (whose points are distinct).
std::array<Point, 4> distinct_four(Random& rng, const std::vector<Point>& pool) {
  std::array<int, 4> k{};
  for (int i = 0; i < 4; ++i) {
    bool repeat = true;
    while (repeat) {
      k[i] = rng.integer(0, static_cast<int>(pool.size()) - 1);
      repeat = std::find(k.begin(), k.begin() + i, k[i]) != k.begin() + i;
    }
  }
  return {pool[k[0]], pool[k[1]], pool[k[2]], pool[k[3]]};
}

// Mismatches with the reference over `trials` quadruples from `pool`; `ties` counts the exact zeros
// of plain incircle among them (so a test can insist that the tie rule was exercised).
int mismatches(const std::vector<Point>& pool, int trials, std::uint64_t seed, int& ties) {
  Predicates pred;
  Random rng(seed);
  int bad = 0;
  for (int i = 0; i < trials; ++i) {
    const auto [a, b, c, d] = distinct_four(rng, pool);
    const double plain = pred.incircle(a, b, c, d);
    const int got = sign_of(pred.incircle_perturbed(a, b, c, d));
    ties += plain == 0.0;
    if (got != perturbed_incircle_sign(a, b, c, d)) ++bad;
    if (plain != 0.0 && got != sign_of(plain)) ++bad;  // no change off the ties
    if (pred.orient2d(a, b, c) != 0.0 && got == 0) ++bad;  // a proper triangle never ties
  }
  return bad;
}

std::vector<Point> lattice(int side, double step, Point origin) {
  std::vector<Point> pts;
  for (int i = 0; i < side; ++i)
    for (int j = 0; j < side; ++j) pts.push_back({origin.x + i * step, origin.y + j * step});
  return pts;
}

}  // namespace

// Small lattices: squares, rectangles, trapezoids and other cocircular quadruples, and collinear
// triples in every position, at several scales and offsets.
TEST(perturbed_incircle_on_lattices) {
  int ties = 0;
  CHECK_EQ(mismatches(lattice(5, 1.0, {0, 0}), 20000, 1, ties), 0);
  CHECK_EQ(mismatches(lattice(4, 0.25, {-0.5, 0.75}), 20000, 2, ties), 0);
  CHECK_EQ(mismatches(lattice(6, 1e-3, {1e6, -1e6}), 20000, 3, ties), 0);
  CHECK_EQ(mismatches(lattice(3, 3.0, {0, 0}), 5000, 4, ties), 0);
  CHECK(ties > 2000);
}

// Every quadruple exactly cocircular: the lattice points of x^2 + y^2 = 65^2 (and the circle moved
// off the origin), so the answer is the tie rule's every time.
TEST(perturbed_incircle_on_a_lattice_circle) {
  std::vector<Point> circle, moved;
  for (int x = -65; x <= 65; ++x)
    for (int y = -65; y <= 65; ++y)
      if (x * x + y * y == 65 * 65) {
        circle.push_back({double(x), double(y)});
        moved.push_back({x * 0.5 + 10.0, y * 0.5 - 3.0});
      }
  CHECK(circle.size() >= 30u);
  int ties = 0;
  CHECK_EQ(mismatches(circle, 20000, 5, ties), 0);
  CHECK_EQ(ties, 20000);
  CHECK_EQ(mismatches(moved, 20000, 6, ties), 0);
  CHECK_EQ(ties, 40000);
}

// A regular polygon's rounded vertices, made exactly symmetric about both axes and both diagonals
// (near ties, and exact ones: any two mirror pairs), its centre, and random points.
TEST(perturbed_incircle_on_polygons_and_random_points) {
  std::vector<Point> polygon{{0, 0}};
  for (int i = 0; i < 6; ++i) {
    const double x = std::cos(i * M_PI / 24), y = std::sin(i * M_PI / 24);
    for (const Point p : {Point{x, y}, Point{y, x}})
      for (const Point s : {Point{1, 1}, Point{-1, 1}, Point{1, -1}, Point{-1, -1}}) {
        const Point q{s.x * p.x, s.y * p.y};  // the points on the axes come twice (-0 == 0)
        if (std::find(polygon.begin(), polygon.end(), q) == polygon.end()) polygon.push_back(q);
      }
  }
  int ties = 0;
  CHECK_EQ(mismatches(polygon, 20000, 7, ties), 0);
  CHECK(ties > 50);
  Random rng(8);
  std::vector<Point> random;
  for (int i = 0; i < 200; ++i) random.push_back(rng.point(-1, 1));
  CHECK_EQ(mismatches(random, 5000, 9, ties), 0);
}

// The rule's documented case: a square keeps the diagonal through its lower left corner.
TEST(perturbed_incircle_square_diagonal) {
  Predicates pred;
  const Point a{0, 0}, b{1, 0}, c{1, 1}, d{0, 1};
  CHECK(pred.incircle_perturbed(a, b, c, d) < 0);  // edge a-c stays
  CHECK(pred.incircle_perturbed(b, c, d, a) > 0);  // edge b-d is flipped away
}
