// BigVector and BigBytes behave like the ordinary containers on both sides of the 4 MiB line
// (ordinary memory below it, a mapping of its own above it).
#include <cstdint>
#include <cstring>
#include <numeric>

#include "harness/check.h"
#include "util/big_allocator.h"

using namespace deltri;

TEST(big_vector_grows_across_the_mapping_threshold_keeping_values) {
  BigVector<std::uint32_t> v;
  for (std::uint32_t i = 0; i < 3'000'000; ++i) v.push_back(i * 7u);  // 12 MB: passes 4 MiB while growing
  bool same = true;
  for (std::uint32_t i = 0; i < v.size(); ++i) same = same && v[i] == i * 7u;
  CHECK(same);
  v.resize(10);
  v.shrink_to_fit();
  CHECK_EQ(v.size(), 10u);
  CHECK_EQ(v[9], 63u);
}

TEST(big_vector_value_initialises_large_blocks) {
  BigVector<double> v(1'000'000, 0.0);
  BigVector<std::uint32_t> w(2'000'000);
  CHECK_EQ(std::accumulate(v.begin(), v.end(), 0.0), 0.0);
  CHECK_EQ(std::accumulate(w.begin(), w.end(), std::uint64_t{0}), 0u);
  const BigVector<std::uint32_t> copy = w;
  CHECK(copy == w);
}

TEST(big_bytes_small_and_large_are_writable_and_movable) {
  for (std::size_t size : {std::size_t{1}, std::size_t{4096}, kBigBlock - 1, kBigBlock, kBigBlock + 12345}) {
    BigBytes b(size);
    std::memset(b.get(), 'x', size);
    BigBytes moved(std::move(b));
    CHECK(b.get() == nullptr);
    CHECK_EQ(moved.get()[size - 1], 'x');
    BigBytes assigned;
    assigned = std::move(moved);
    CHECK_EQ(assigned.capacity(), size);
  }
}
