// The bucket function and the queue discipline, checked against direct computation.
#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <random>

#include "harness/check.h"
#include "harness/id_literals.h"
#include "refine/quality_queue.h"

using namespace deltri;

namespace {

// How many times x >= 1 halves before it drops below 2 (floor(log2 x) by counting, not from the
// bits); `mantissa` gets what is left, in [1, 2).
unsigned halvings(double x, double* mantissa = nullptr) {
  unsigned count = 0;
  for (; x >= 2.0; x *= 0.5) ++count;
  if (mantissa) *mantissa = x;
  return count;
}

// Checks that key(l2, 1) never falls as l2 shrinks from 1 by `factor` per step down to `floor`;
// returns the key at the end.
template <class Key>
unsigned check_rises_as_edges_shorten(Key key, double floor, double factor) {
  unsigned last = 0;
  for (double l2 = 1.0; l2 > floor; l2 *= factor) {
    const unsigned k = key(l2, 1.0);
    CHECK(k >= last);
    last = k;
  }
  return last;
}

// A queue entry for triangle t with corners a, b, c (numbers, so that tests can use literals).
QueuedTriangle entry(std::uint32_t t, std::uint32_t a = 0, std::uint32_t b = 0, std::uint32_t c = 0) {
  return {TriangleId{t}, VertexId{a}, VertexId{b}, VertexId{c}};
}

// Pops one entry per id and checks that they come out in exactly that order.
void expect_pops(QualityQueue& q, std::initializer_list<std::uint32_t> ids) {
  for (std::uint32_t t : ids) {
    auto e = q.pop();
    REQUIRE(e.has_value());
    CHECK_EQ(e->triangle, t);
  }
}

}  // namespace

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
  q.push_to_bucket(entry(1), 5);
  q.push_to_bucket(entry(2), 40);
  q.push_to_bucket(entry(3), 5);
  q.push_to_bucket(entry(4), 0);
  q.push_to_bucket(entry(5), 40);
  CHECK_EQ(q.size(), 5u);
  expect_pops(q, {2, 5, 1, 3, 4});
  CHECK(q.empty());
  CHECK(!q.pop().has_value());
  CHECK_EQ(q.peak_size(), 5u);
}

TEST(queue_keeps_order_across_reclaiming) {
  QualityQueue q;
  for (TriangleId t{0}; t < 20000; ++t) q.push_to_bucket(entry(t, t, t + 1, t + 2), 7);
  for (TriangleId t{0}; t < 20000; ++t) {
    auto e = q.pop();
    REQUIRE(e.has_value());
    CHECK_EQ(e->triangle, t);
    CHECK_EQ(e->b, t + 1);
    if (t % 3 == 0) q.push_to_bucket(entry(100000 + t), 7);  // interleaved pushes stay behind
  }
  std::uint32_t next = 100000;
  while (auto e = q.pop()) {
    CHECK_EQ(e->triangle, next);
    next += 3;
  }
  CHECK(q.nonempty_mask() == 0);
}

// Chains that mix the first small blocks (64 entries) with 16 KiB ones, in many buckets at once,
// against a model of one FIFO per bucket: every pop takes the oldest entry of the highest
// non-empty bucket, and peek(ahead) names the entry that many places behind it.
TEST(queue_matches_a_model_across_small_and_large_blocks) {
  std::mt19937_64 rng(3);
  std::uniform_int_distribution<unsigned> bucket_of(0, 63), ahead_of(0, 1500);
  std::uniform_real_distribution<double> coin(0.0, 1.0);
  QualityQueue q(QueueOrder::Paper);  // plain FIFO buckets (the ShortestEdge order re-deals bucket 1)
  std::vector<std::vector<std::uint32_t>> model(64);  // per bucket, oldest first
  std::vector<std::size_t> front(64, 0);
  std::uint32_t next = 0;
  const auto top = [&] {
    for (unsigned b = 64; b-- > 0;)
      if (front[b] < model[b].size()) return static_cast<int>(b);
    return -1;
  };
  for (int step = 0; step < 60000; ++step) {
    // Mostly pushes at first (few buckets, then many), mostly pops later.
    const bool push = coin(rng) < (step < 30000 ? 0.7 : 0.3);
    if (push) {
      const unsigned b = step < 3000 ? bucket_of(rng) % 4 : bucket_of(rng);
      q.push_to_bucket(entry(next), b);
      model[b].push_back(next++);
      continue;
    }
    const int b = top();
    if (b >= 0) {
      const std::size_t ahead = ahead_of(rng);
      const QueuedTriangle* seen = q.peek(ahead);
      const std::size_t at = front[b] + ahead;
      if (at < model[b].size()) {
        REQUIRE(seen != nullptr);
        CHECK_EQ(seen->triangle, model[b][at]);
      } else {
        CHECK(seen == nullptr);
      }
    }
    auto e = q.pop();
    if (b < 0) {
      CHECK(!e.has_value());
      continue;
    }
    REQUIRE(e.has_value());
    CHECK_EQ(e->triangle, model[b][front[b]++]);
  }
  while (top() >= 0) {
    auto e = q.pop();
    REQUIRE(e.has_value());
    const int b = top();
    CHECK_EQ(e->triangle, model[b][front[b]++]);
  }
  CHECK(q.empty());
}

TEST(edge_bucket_is_one_plus_log2_of_the_squared_length_ratio) {
  // Checked against an integer count of halvings, not against frexp.
  std::mt19937_64 rng(2);
  std::uniform_real_distribution<double> u(0.0, 70.0);
  for (int i = 0; i < 100000; ++i) {
    const double ratio = std::exp2(u(rng));
    const unsigned expected = std::min(63u, 1u + halvings(ratio));
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
  CHECK_EQ(check_rises_as_edges_shorten(edge_bucket, 1e-25, 0.97), 63u);
}

TEST(keyed_queue_serves_largest_key_first_and_oldest_among_equals) {
  QualityQueue q;
  const double keys[] = {3.0, 0.0, 7.5, 3.0, 1e300, 0.0, 7.5};
  for (TriangleId t{0}; t < 7; ++t) q.push_keyed(entry(t), 1, keys[t]);
  CHECK_EQ(q.size(), 7u);
  expect_pops(q, {4, 2, 6, 0, 3, 1, 5});
  CHECK(q.empty());
  CHECK(!q.pop().has_value());
}

TEST(keyed_queue_serves_higher_tiers_first_whatever_the_key) {
  QualityQueue q;
  q.push_keyed(entry(1), 0, 1e300);
  q.push_keyed(entry(2), 2, 1.0);
  q.push_keyed(entry(3), 1, 1e300);
  q.push_keyed(entry(4), 2, 5.0);
  expect_pops(q, {4, 2, 3, 1});
}

// Through the queue: the ShortestEdge order serves skinny triangles by their shortest edge, shortest
// first, whatever their ratio: a sliver as long as the domain waits behind a mildly skinny
// triangle with a tiny edge; triangles that are only too large come last.
TEST(ratio_order_serves_slivers_by_their_shortest_edge_like_the_rest) {
  QualityQueue q(QueueOrder::ShortestEdge, 1.0);
  q.push(entry(1), {true, 255.9, 1e-20});  // mildly skinny, tiny edge
  q.push(entry(2), {false, 0.5, 1e-30});   // too large only
  q.push(entry(3), {true, 256.0, 1.0});    // a sliver as long as the domain
  q.push(entry(4), {true, 1e6, 1e-4});     // a worse sliver, shorter edge
  q.push(entry(5), {true, 2.0, 1e-10});    // mildly skinny, longer edge than 1's
  expect_pops(q, {1, 5, 4, 3, 2});
}

// The edge level: four per octave of D^2 / l^2, checked against halvings and the quarter marks
// of the mantissa computed by division, not from the bits.
TEST(edge_level_is_four_per_octave_of_the_squared_length_ratio) {
  std::mt19937_64 rng(4);
  std::uniform_real_distribution<double> u(0.0, 80.0);
  for (int i = 0; i < 100000; ++i) {
    const double x = std::exp2(u(rng));
    double m = 0.0;
    const unsigned octaves = halvings(x, &m);
    const unsigned quarter = m >= 1.75 ? 3 : m >= 1.5 ? 2 : m >= 1.25 ? 1 : 0;
    CHECK_EQ(edge_level(1.0 / x, 1.0), 4 * octaves + quarter);
    CHECK_EQ(edge_level(8.0, 8.0 * x), 4 * octaves + quarter);  // only the ratio matters
  }
  CHECK_EQ(edge_level(1.0, 1.0), 0u);
  CHECK_EQ(edge_level(4.0, 1.0), 0u);              // longer than the reference
  CHECK_EQ(edge_level(1.0 / 1.25, 1.0), 1u);
  CHECK_EQ(edge_level(0.5, 1.0), 4u);
  CHECK_EQ(edge_level(0.0, 1.0), kTopLevel);       // degenerate: the most urgent
}

// The fine levels (above 30 degrees): 16 per octave of D^2 / l^2, the sixteenth marks of the
// mantissa again by division.
TEST(fine_edge_level_is_sixteen_per_octave_of_the_squared_length_ratio) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0.0, 80.0);
  for (int i = 0; i < 100000; ++i) {
    const double x = std::exp2(u(rng));
    double m = 0.0;
    const unsigned octaves = halvings(x, &m);
    unsigned sixteenth = 0;
    while (sixteenth < 15 && m >= 1.0 + (sixteenth + 1) / 16.0) ++sixteenth;
    CHECK_EQ(edge_level(1.0 / x, 1.0, kFineLevelBits), 16 * octaves + sixteenth);
  }
  CHECK_EQ(edge_level(0.5, 1.0, kFineLevelBits), 16u);
  CHECK_EQ(edge_level(0.0, 1.0, kFineLevelBits), kTopLevel);
  CHECK(edge_level(1e-300, 1.0, kFineLevelBits) < kTopLevel);  // the finest real level stays below the top
  CHECK_EQ(edge_level_bits(30.0), kCoarseLevelBits);
  CHECK_EQ(edge_level_bits(30.5), kFineLevelBits);
}

TEST(edge_level_ranks_shorter_edges_higher) {
  for (unsigned bits : {kCoarseLevelBits, kFineLevelBits})
    check_rises_as_edges_shorten([bits](double l2, double r2) { return edge_level(l2, r2, bits); }, 1e-200, 0.93);
}

// The ShortestEdge order through the queue: size-only last, and every pop takes the shortest edge present (an exact order by level, FIFO within a level),
// across levels spread over 60 octaves, which takes several moves of the window. Checked against
// a plain sorted model, not against the buckets.
void check_ratio_order_across_window_moves(unsigned bits) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0.0, 120.0);
  QualityQueue q(QueueOrder::ShortestEdge, 1.0, bits);
  struct Model { unsigned level; TriangleId id; };
  std::vector<Model> model;
  for (TriangleId t{0}; t < 20000; ++t) {
    const double l2 = std::exp2(-u(rng));
    q.push(entry(t), {true, 2.0, l2});
    model.push_back({edge_level(l2, 1.0, bits), t});
  }
  q.push(entry(100000), {false, 0.5, 1e-300});  // too large only
  q.push(entry(100001), {true, 300.0, 1.0});    // a sliver with a long edge: by its edge too
  model.push_back({edge_level(1.0, 1.0, bits), TriangleId{100001}});
  std::stable_sort(model.begin(), model.end(), [](const Model& a, const Model& b) { return a.level > b.level; });
  for (const Model& m : model) {
    auto e = q.pop();
    REQUIRE(e.has_value());
    CHECK_EQ(e->triangle, m.id);
  }
  auto last = q.pop();
  REQUIRE(last.has_value());
  CHECK_EQ(last->triangle, 100000u);
  CHECK(q.empty());
  CHECK(q.nonempty_mask() == 0);
}

TEST(ratio_order_serves_mild_triangles_shortest_first_across_window_moves) {
  for (unsigned bits : {kCoarseLevelBits, kFineLevelBits}) check_ratio_order_across_window_moves(bits);
}

// Pushes while popping, as refinement does: a split makes triangles at most kWindowHeadroom levels
// shorter than the one it split. Every pop must still take a shortest edge present.
void check_ratio_order_while_pushing_shorter_edges(unsigned bits) {
  std::mt19937_64 rng(6);
  std::uniform_real_distribution<double> start(0.0, 60.0);
  std::uniform_int_distribution<int> offset(-40, static_cast<int>(kWindowHeadroom) - 1);
  QualityQueue q(QueueOrder::ShortestEdge, 1.0, bits);
  const unsigned per_octave = 1u << bits;  // levels per octave of the squared length ratio
  std::vector<std::pair<unsigned, TriangleId>> live;  // the model: levels of the queued triangles
  TriangleId next{0};
  const auto push_level = [&](double l2) {
    q.push(entry(next), {true, 3.0, l2});
    live.push_back({edge_level(l2, 1.0, bits), next++});
  };
  for (int i = 0; i < 2000; ++i) push_level(std::exp2(-start(rng)));
  for (int step = 0; step < 30000 && !live.empty(); ++step) {
    auto e = q.pop();
    REQUIRE(e.has_value());
    unsigned best = 0;
    for (const auto& [level, id] : live) best = std::max(best, level);
    const auto it = std::find_if(live.begin(), live.end(), [&](const auto& m) { return m.second == e->triangle; });
    REQUIRE(it != live.end());
    const unsigned popped = it->first;  // the popped triangle's level, from the model
    CHECK_EQ(popped, best);
    live.erase(it);
    if (step < 20000)
      for (int k = 0; k < 2; ++k) {  // children near the popped scale, a few levels finer at most
        const int level = std::max(static_cast<int>(popped) + offset(rng), 0);
        // A squared length whose level is exactly `level`: x = (1 + (k + 1/2) / n) 2^(level / n),
        // k = level mod n, n levels per octave.
        const int n = static_cast<int>(per_octave);
        const double x = (1.0 + (level % n + 0.5) / n) * std::exp2(level / n);
        push_level(1.0 / x);
      }
  }
}

TEST(ratio_order_stays_exact_while_refinement_pushes_shorter_edges) {
  for (unsigned bits : {kCoarseLevelBits, kFineLevelBits}) check_ratio_order_while_pushing_shorter_edges(bits);
}

TEST(paper_order_serves_worst_ratio_first_whatever_the_edge) {
  QualityQueue q(QueueOrder::Paper, 1.0);
  q.push(entry(1), {true, 2.0, 1e-30});
  q.push(entry(2), {true, 100.0, 1.0});
  q.push(entry(3), {false, 0.0, 1e-30});
  expect_pops(q, {2, 1, 3});
}
