// SmallVector (util/small_vector.h) against std::vector through the move from in place to the heap.
#include <vector>

#include "harness/check.h"
#include "util/small_vector.h"

TEST(small_vector_keeps_order_across_the_move_to_the_heap) {
  deltri::SmallVector<int, 4> v;
  std::vector<int> want;
  for (int i = 0; i < 10; ++i) {
    v.push_back(i * i);
    want.push_back(i * i);
    REQUIRE(v.size() == want.size());
    CHECK(std::vector<int>(v.begin(), v.end()) == want);
    CHECK_EQ(v.back(), want.back());
  }
  for (int i = 0; i < 7; ++i) {  // back below the in-place size, still in order
    v.pop_back();
    want.pop_back();
    CHECK(std::vector<int>(v.begin(), v.end()) == want);
  }
  v.push_back(-1);
  want.push_back(-1);
  CHECK(std::vector<int>(v.begin(), v.end()) == want);
  for (std::size_t i = 0; i < want.size(); ++i) CHECK_EQ(v[i], want[i]);
  while (!v.empty()) v.pop_back();
  CHECK_EQ(v.size(), std::size_t{0});
}
