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

TEST(edge_bucket_is_one_plus_log2_of_the_squared_length_ratio) {
  // Checked against an integer count of halvings, not against frexp.
  std::mt19937_64 rng(2);
  std::uniform_real_distribution<double> u(0.0, 70.0);
  for (int i = 0; i < 100000; ++i) {
    const double ratio = std::exp2(u(rng));
    unsigned halvings = 0;
    for (double r = ratio; r >= 2.0; r *= 0.5) ++halvings;
    const unsigned expected = std::min(63u, 1u + halvings);
    CHECK_EQ(edge_bucket(1.0 / ratio, 1.0), expected);
    CHECK_EQ(edge_bucket(4.0, 4.0 * ratio), expected);  // only the ratio matters
  }
  CHECK_EQ(edge_bucket(1.0, 1.0), 1u);
  CHECK_EQ(edge_bucket(0.5, 1.0), 2u);
  CHECK_EQ(edge_bucket(0.499, 1.0), 2u);
  CHECK_EQ(edge_bucket(0.25, 1.0), 3u);
  CHECK_EQ(edge_bucket(4.0, 1.0), 1u);    // longer than the reference: the least urgent
  CHECK_EQ(edge_bucket(0.0, 1.0), 63u);   // degenerate: the most urgent
  CHECK_EQ(edge_bucket(1e-300, 1e300), 63u);
}

TEST(edge_bucket_ranks_shorter_edges_higher) {
  unsigned last = 0;
  for (double l2 = 1.0; l2 > 1e-25; l2 *= 0.97) {
    const unsigned b = edge_bucket(l2, 1.0);
    CHECK(b >= last);
    last = b;
  }
  CHECK_EQ(last, 63u);
}

TEST(keyed_queue_serves_largest_key_first_and_oldest_among_equals) {
  QualityQueue q;
  const double keys[] = {3.0, 0.0, 7.5, 3.0, 1e300, 0.0, 7.5};
  for (TriangleId t = 0; t < 7; ++t) q.push_keyed({t, 0, 0, 0}, keys[t]);
  CHECK_EQ(q.size(), 7u);
  const TriangleId expected[] = {4, 2, 6, 0, 3, 1, 5};
  for (TriangleId t : expected) {
    auto e = q.pop();
    REQUIRE(e.has_value());
    CHECK_EQ(e->triangle, t);
  }
  CHECK(q.empty());
  CHECK(!q.pop().has_value());
}
