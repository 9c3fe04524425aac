// The Hilbert order (geometry/hilbert.h) against the curve's defining property: cells that follow
// each other along the curve share a side.
#include <cstdint>
#include <cstdlib>
#include <vector>

#include "geometry/hilbert.h"
#include "harness/check.h"

namespace {

using deltri::Point;

}  // namespace

TEST(hilbert_order_visits_a_lattice_cell_by_neighbouring_cell) {
  // The lattice points of a 32 x 32 grid of cells of side 2048 on the curve's 65536 x 65536 grid,
  // plus a point at the far corner that makes the box the whole grid (one grid cell per unit).
  const int n = 32, side = 65536 / n;
  std::vector<Point> points;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) points.push_back(Point{double(i * side), double(j * side)});
  points.push_back(Point{65535.0, 65535.0});
  const std::uint32_t corner = n * n;
  const std::vector<std::uint32_t> order = deltri::hilbert_order(points);
  REQUIRE(order.size() == points.size());
  std::vector<int> seen(points.size(), 0);
  for (const std::uint32_t i : order) ++seen[i];
  for (const int s : seen) CHECK_EQ(s, 1);
  std::uint32_t previous = corner;
  int steps = 0;
  for (const std::uint32_t i : order) {
    if (i == corner) continue;
    if (previous != corner) {
      const double d = std::abs(points[i].x - points[previous].x) + std::abs(points[i].y - points[previous].y);
      CHECK_EQ(d, double(side));
      ++steps;
    }
    previous = i;
  }
  CHECK_EQ(steps, n * n - 1);
}

TEST(hilbert_order_keeps_equal_points_in_index_order) {
  const std::vector<Point> points{{1, 1}, {0, 0}, {1, 1}, {0, 0}, {1, 1}};
  const std::vector<std::uint32_t> order = deltri::hilbert_order(points);
  REQUIRE(order.size() == 5u);
  // (0, 0) is the curve's start; equal points keep their order.
  CHECK_EQ(order[0], 1u);
  CHECK_EQ(order[1], 3u);
  CHECK_EQ(order[2], 0u);
  CHECK_EQ(order[3], 2u);
  CHECK_EQ(order[4], 4u);
}
