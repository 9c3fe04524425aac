// The bucket function and the queue discipline, checked against direct computation.
#include <cmath>
#include <random>

#include "harness/check.h"
#include "refine/quality_queue.h"

using namespace deltri;

TEST(bucket_zero_is_size_only) { CHECK_EQ(quality_bucket(0.0), 0u); }

TEST(bucket_follows_exponent_and_first_mantissa_bit) {
  // q = m 2^k: [2^k, 1.5 2^k) -> 1 + 2k ; [1.5 2^k, 2^(k+1)) -> 2 + 2k, until bucket 63.
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> u(0.0, 40.0);
  for (int i = 0; i < 100000; ++i) {
    const double lg = u(rng);
    const double q = std::exp2(lg);
    int k = 0;
    const double m = 2.0 * std::frexp(q, &k);  // q = m 2^(k-1), 1 <= m < 2
    const double steps = 2.0 * (k - 1) + (m >= 1.5 ? 1.0 : 0.0);
    const unsigned expected = static_cast<unsigned>(std::min(63.0, 1.0 + steps));
    CHECK_EQ(quality_bucket(q), expected);
  }
  CHECK_EQ(quality_bucket(1.0), 1u);
  CHECK_EQ(quality_bucket(1.499), 1u);
  CHECK_EQ(quality_bucket(1.5), 2u);
  CHECK_EQ(quality_bucket(1.999), 2u);
  CHECK_EQ(quality_bucket(2.0), 3u);
  CHECK_EQ(quality_bucket(1e300), 63u);
  CHECK_EQ(quality_bucket(INFINITY), 63u);
}

TEST(bucket_is_monotone_in_the_ratio) {
  unsigned last = 0;
  for (double q = 1.0; q < 1e12; q *= 1.01) {
    const unsigned b = quality_bucket(q);
    CHECK(b >= last);
    last = b;
  }
}

TEST(queue_serves_worst_bucket_first_and_fifo_within) {
  QualityQueue q;
  q.push({1, 0, 0, 0}, 5);
  q.push({2, 0, 0, 0}, 40);
  q.push({3, 0, 0, 0}, 5);
  q.push({4, 0, 0, 0}, 0);
  q.push({5, 0, 0, 0}, 40);
  CHECK_EQ(q.size(), 5u);
  const TriangleId expected[] = {2, 5, 1, 3, 4};
  for (TriangleId t : expected) {
    auto e = q.pop();
    REQUIRE(e.has_value());
    CHECK_EQ(e->triangle, t);
  }
  CHECK(q.empty());
  CHECK(!q.pop().has_value());
  CHECK_EQ(q.peak_size(), 5u);
}

TEST(queue_keeps_order_across_reclaiming) {
  QualityQueue q;
  for (TriangleId t = 0; t < 20000; ++t) q.push({t, t, t + 1, t + 2}, 7);
  for (TriangleId t = 0; t < 20000; ++t) {
    auto e = q.pop();
    REQUIRE(e.has_value());
    CHECK_EQ(e->triangle, t);
    CHECK_EQ(e->b, t + 1);
    if (t % 3 == 0) q.push({100000 + t, 0, 0, 0}, 7);  // interleaved pushes stay behind
  }
  TriangleId next = 100000;
  while (auto e = q.pop()) {
    CHECK_EQ(e->triangle, next);
    next += 3;
  }
  CHECK(q.nonempty_mask() == 0);
}
