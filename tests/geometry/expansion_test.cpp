// Expansion arithmetic checked against the independent big-integer evaluator.
#include <cmath>
#include <vector>

#include "geometry/expansion.h"
#include "geometry/exact_reference.h"
#include "geometry/random_support.h"
#include "harness/check.h"

namespace {

using namespace deltri::expansion;
using reference::Dyadic;
using reference::exact_sum;
using testing_support::Random;

bool same_value(const Dyadic& a, const Dyadic& b) { return (a - b).sign() == 0; }

// A double with random sign, mantissa and exponent in [-exp_range, exp_range].
double wild(Random& rng, int exp_range) {
  const double m = rng.uniform(0.5, 1.0) * (rng.integer(0, 1) ? 1.0 : -1.0);
  return std::ldexp(m, rng.integer(-exp_range, exp_range));
}

// Lowest set bit of a nonzero double, as a power of two.
double lowest_bit(double v) {
  int e = 0;
  const double f = std::frexp(std::fabs(v), &e);
  auto m = static_cast<std::uint64_t>(std::ldexp(f, 53));
  int zeros = 0;
  while ((m & 1u) == 0) {
    m >>= 1;
    ++zeros;
  }
  return std::ldexp(1.0, e - 53 + zeros);
}

// Components nonzero, increasing, and each entirely below the lowest bit of the next.
bool well_formed(const double* e, int n) {
  for (int i = 0; i < n; ++i) {
    if (e[i] == 0.0) return false;
    if (i + 1 < n && !(std::fabs(e[i]) < lowest_bit(e[i + 1]))) return false;
  }
  return true;
}

std::vector<double> random_expansion(Random& rng, int terms, int exp_range) {
  std::vector<double> e;
  for (int i = 0; i < terms; ++i) {
    std::vector<double> h(e.size() + 1);
    const int n = grow(e.data(), static_cast<int>(e.size()), wild(rng, exp_range), h.data());
    h.resize(n);
    e = h;
  }
  return e;
}

}  // namespace

TEST(expansion_error_free_transformations_are_exact) {
  Random rng(1);
  for (int i = 0; i < 20000; ++i) {
    const double a = wild(rng, 300), b = wild(rng, i % 2 ? 300 : 40);
    double x, y;
    two_sum(a, b, x, y);
    CHECK(x == a + b);
    CHECK(same_value(Dyadic(x) + Dyadic(y), Dyadic(a) + Dyadic(b)));
    two_diff(a, b, x, y);
    CHECK(x == a - b);
    CHECK(same_value(Dyadic(x) + Dyadic(y), Dyadic(a) - Dyadic(b)));
    two_product(a, b, x, y);
    CHECK(x == a * b);
    CHECK(same_value(Dyadic(x) + Dyadic(y), Dyadic(a) * Dyadic(b)));
    const double big = std::fabs(a) >= std::fabs(b) ? a : b, small = big == a ? b : a;
    fast_two_sum(big, small, x, y);
    CHECK(same_value(Dyadic(x) + Dyadic(y), Dyadic(a) + Dyadic(b)));
  }
}

TEST(expansion_grow_scale_sum_multiply_are_exact) {
  Random rng(2);
  for (int i = 0; i < 3000; ++i) {
    const int range = i % 3 == 0 ? 200 : 30;
    const auto e = random_expansion(rng, rng.integer(0, 8), range);
    const auto f = random_expansion(rng, rng.integer(0, 8), range);
    const int en = static_cast<int>(e.size()), fn = static_cast<int>(f.size());
    REQUIRE(well_formed(e.data(), en));
    const double b = wild(rng, range);

    std::vector<double> h(2 * en * (fn + 1) + en + fn + 2), scratch(2 * en * (fn + 1) + 2);
    int n = grow(e.data(), en, b, h.data());
    CHECK(well_formed(h.data(), n));
    CHECK(same_value(exact_sum(h.data(), n), exact_sum(e.data(), en) + Dyadic(b)));

    n = scale(e.data(), en, b, h.data());
    CHECK(well_formed(h.data(), n));
    CHECK(same_value(exact_sum(h.data(), n), exact_sum(e.data(), en) * Dyadic(b)));

    n = sum(e.data(), en, f.data(), fn, h.data());
    CHECK(well_formed(h.data(), n));
    CHECK(same_value(exact_sum(h.data(), n), exact_sum(e.data(), en) + exact_sum(f.data(), fn)));

    n = multiply(e.data(), en, f.data(), fn, h.data(), scratch.data());
    CHECK(well_formed(h.data(), n));
    CHECK(same_value(exact_sum(h.data(), n), exact_sum(e.data(), en) * exact_sum(f.data(), fn)));
    CHECK_EQ(sign(h.data(), n), exact_sum(h.data(), n).sign());
    CHECK_EQ(testing_support::sign_of(signed_estimate(h.data(), n)), exact_sum(h.data(), n).sign());
  }
}

TEST(expansion_difference_of_products_is_exact_including_cancellation) {
  Random rng(3);
  for (int i = 0; i < 10000; ++i) {
    const double a = wild(rng, 50), b = wild(rng, 50);
    // c * d equal or very close to a * b, to force cancellation.
    const double c = i % 2 ? a : testing_support::nudge(a, rng.integer(-3, 3));
    const double d = i % 3 ? b : testing_support::nudge(b, rng.integer(-3, 3));
    double h[4];
    const int n = difference_of_products(a, b, c, d, h);
    CHECK(well_formed(h, n));
    const Dyadic expected = Dyadic(a) * Dyadic(b) - Dyadic(c) * Dyadic(d);
    CHECK(same_value(exact_sum(h, n), expected));
    CHECK_EQ(sign(h, n), expected.sign());
  }
}

TEST(expansion_empty_is_zero) {
  double h[4];
  CHECK_EQ(grow(nullptr, 0, 0.0, h), 0);
  CHECK_EQ(scale(nullptr, 0, 3.0, h), 0);
  CHECK_EQ(sum(nullptr, 0, nullptr, 0, h), 0);
  CHECK_EQ(sign(h, 0), 0);
  CHECK_EQ(estimate(h, 0), 0.0);
  CHECK_EQ(difference_of_products(3.0, 5.0, 5.0, 3.0, h), 0);
}
