// The bucket function and the queue discipline, checked against direct computation.
#include <cmath>
#include <random>

#include "harness/check.h"
#include "refine/quality_queue.h"

using namespace deltri;

TEST(paper_bucket_zero_is_size_only) { CHECK_EQ(paper_bucket(0.0), 0u); }

TEST(paper_bucket_follows_exponent_and_first_mantissa_bit) {
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
    CHECK_EQ(paper_bucket(q), expected);
  }
  CHECK_EQ(paper_bucket(1.0), 1u);
  CHECK_EQ(paper_bucket(1.499), 1u);
  CHECK_EQ(paper_bucket(1.5), 2u);
  CHECK_EQ(paper_bucket(1.999), 2u);
  CHECK_EQ(paper_bucket(2.0), 3u);
  CHECK_EQ(paper_bucket(1e300), 63u);
  CHECK_EQ(paper_bucket(INFINITY), 63u);
}

TEST(paper_bucket_is_monotone_in_the_ratio) {
  unsigned last = 0;
  for (double q = 1.0; q < 1e12; q *= 1.01) {
    const unsigned b = paper_bucket(q);
    CHECK(b >= last);
    last = b;
  }
}

TEST(queue_serves_worst_bucket_first_and_fifo_within) {
  QualityQueue q;
  q.push_to_bucket({1, 0, 0, 0}, 5);
  q.push_to_bucket({2, 0, 0, 0}, 40);
  q.push_to_bucket({3, 0, 0, 0}, 5);
  q.push_to_bucket({4, 0, 0, 0}, 0);
  q.push_to_bucket({5, 0, 0, 0}, 40);
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
  for (TriangleId t = 0; t < 20000; ++t) q.push_to_bucket({t, t, t + 1, t + 2}, 7);
  for (TriangleId t = 0; t < 20000; ++t) {
    auto e = q.pop();
    REQUIRE(e.has_value());
    CHECK_EQ(e->triangle, t);
    CHECK_EQ(e->b, t + 1);
    if (t % 3 == 0) q.push_to_bucket({100000 + t, 0, 0, 0}, 7);  // interleaved pushes stay behind
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
  for (TriangleId t = 0; t < 7; ++t) q.push_keyed({t, 0, 0, 0}, 1, keys[t]);
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

TEST(keyed_queue_serves_higher_tiers_first_whatever_the_key) {
  QualityQueue q;
  q.push_keyed({1, 0, 0, 0}, 0, 1e300);
  q.push_keyed({2, 0, 0, 0}, 2, 1.0);
  q.push_keyed({3, 0, 0, 0}, 1, 1e300);
  q.push_keyed({4, 0, 0, 0}, 2, 5.0);
  const TriangleId expected[] = {4, 2, 3, 1};
  for (TriangleId t : expected) {
    auto e = q.pop();
    REQUIRE(e.has_value());
    CHECK_EQ(e->triangle, t);
  }
}

// The default key, checked against its definition computed independently: size-only triangles in
// bucket 0; mildly skinny ones (B < r < 4B) by the count of halvings from D^2 down to l^2, into
// 1..47; skinny ones (r >= 4B) by the count of doublings of q from 16, into 48..63.
TEST(ratio_bucket_has_two_tiers_split_at_four_times_the_bound) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> lq(0.0, 30.0), ll(0.0, 60.0);
  for (int i = 0; i < 100000; ++i) {
    const double q = std::exp2(lq(rng));
    const double shortest2 = std::exp2(-ll(rng));  // D^2 = 1
    const unsigned b = ratio_bucket({true, q, shortest2}, 1.0);
    if (q < 16.0) {
      unsigned halvings = 0;
      for (double r = 1.0 / shortest2; r >= 2.0; r *= 0.5) ++halvings;
      const unsigned expected = std::min(47u, 1u + halvings);
      CHECK_EQ(b, expected);
    } else {
      unsigned doublings = 0;
      for (double r = q / 16.0; r >= 2.0; r *= 0.5) ++doublings;
      const unsigned expected = std::min(63u, 48u + doublings);
      CHECK_EQ(b, expected);
    }
  }
  CHECK_EQ(ratio_bucket({false, 1e6, 1e-20}, 1.0), 0u);           // size only, whatever its shape
  CHECK_EQ(ratio_bucket({true, 15.999, 1.0}, 1.0), 1u);           // mild, as long as D
  CHECK_EQ(ratio_bucket({true, 15.999, 1e-30}, 1.0), 47u);        // mild, tiny edge
  CHECK_EQ(ratio_bucket({true, 16.0, 1e-30}, 1.0), 48u);          // skinny: the edge no longer counts
  CHECK_EQ(ratio_bucket({true, 16.0 * 3.9, 1.0}, 1.0), 49u);
  CHECK_EQ(ratio_bucket({true, INFINITY, 1.0}, 1.0), 63u);        // flat
  CHECK_EQ(ratio_bucket({true, 4.0, 0.0}, 1.0), 47u);             // zero-length shortest edge
}

TEST(ratio_bucket_puts_every_skinny_triangle_above_every_mild_one) {
  for (double q = 1.0; q < 1e10; q *= 1.07)
    for (double l2 = 1.0; l2 > 1e-40; l2 *= 0.31) {
      const unsigned b = ratio_bucket({true, q, l2}, 1.0);
      CHECK(b >= 1u);
      CHECK((q >= 16.0) == (b >= 48u));
    }
}

// Through the queue itself: with the default order a skinny triangle is served before a mildly
// skinny one with a far shorter edge, and among the mild ones the shorter edge goes first.
TEST(ratio_order_serves_skinny_by_ratio_then_mild_by_edge) {
  QualityQueue q(QueueOrder::Ratio, 1.0);
  q.push({1, 0, 0, 0}, {true, 2.0, 1e-2});    // mild, long edge
  q.push({2, 0, 0, 0}, {false, 0.5, 1e-9});   // too large only
  q.push({3, 0, 0, 0}, {true, 2.0, 1e-8});    // mild, short edge
  q.push({4, 0, 0, 0}, {true, 100.0, 1.0});   // skinny
  q.push({5, 0, 0, 0}, {true, 1e4, 1.0});     // skinnier
  const TriangleId expected[] = {5, 4, 3, 1, 2};
  for (TriangleId t : expected) {
    auto e = q.pop();
    REQUIRE(e.has_value());
    CHECK_EQ(e->triangle, t);
  }
  QualityQueue heap(QueueOrder::RatioHeap, 1.0);
  heap.push({1, 0, 0, 0}, {true, 2.0, 1e-2});
  heap.push({2, 0, 0, 0}, {false, 0.5, 1e-9});
  heap.push({3, 0, 0, 0}, {true, 2.0, 1.1e-2});  // the same bucket as 1, but exactly shorter
  heap.push({4, 0, 0, 0}, {true, 100.0, 1.0});
  heap.push({5, 0, 0, 0}, {true, 101.0, 1.0});
  const TriangleId exact[] = {5, 4, 1, 3, 2};
  for (TriangleId t : exact) {
    auto e = heap.pop();
    REQUIRE(e.has_value());
    CHECK_EQ(e->triangle, t);
  }
}

TEST(paper_order_serves_worst_ratio_first_whatever_the_edge) {
  QualityQueue q(QueueOrder::Paper, 1.0);
  q.push({1, 0, 0, 0}, {true, 2.0, 1e-30});
  q.push({2, 0, 0, 0}, {true, 100.0, 1.0});
  q.push({3, 0, 0, 0}, {false, 0.0, 1e-30});
  const TriangleId expected[] = {2, 1, 3};
  for (TriangleId t : expected) {
    auto e = q.pop();
    REQUIRE(e.has_value());
    CHECK_EQ(e->triangle, t);
  }
}
