// The doubles near a point (geometry/lattice.h).
#include <cmath>
#include <set>
#include <utility>
#include <vector>

#include "geometry/lattice.h"
#include "harness/check.h"

namespace {

using deltri::Point;

}  // namespace

TEST(lattice_neighbourhood_lists_every_double_within_the_steps_once) {
  std::vector<Point> out;
  const Point c{41.77377931209348, 55.45235951180828};
  deltri::lattice_neighbourhood(c, 2, out);
  REQUIRE(out.size() == 25u);
  CHECK(out[0] == c);
  std::set<std::pair<double, double>> seen;
  for (const Point& p : out) {
    seen.insert({p.x, p.y});
    CHECK(std::fabs(p.x - c.x) <= 2 * 7.2e-15);
    CHECK(std::fabs(p.y - c.y) <= 2 * 7.2e-15);
  }
  CHECK_EQ(seen.size(), std::size_t{25});
  // The first ring (the 8 points one step away) comes before the second.
  for (std::size_t i = 1; i < 9; ++i) CHECK(std::fabs(out[i].x - c.x) <= 7.2e-15 && std::fabs(out[i].y - c.y) <= 7.2e-15);
}

TEST(lattice_neighbourhood_follows_each_axis_across_powers_of_two) {
  std::vector<Point> out;
  deltri::lattice_neighbourhood({1.0, 3.0}, 1, out);
  REQUIRE(out.size() == 9u);
  std::set<double> xs, ys;
  for (const Point& p : out) xs.insert(p.x), ys.insert(p.y);
  // Below 1 the doubles are twice as dense as above it; each axis steps on its own lattice.
  CHECK(xs == (std::set<double>{1.0 - 0x1p-53, 1.0, 1.0 + 0x1p-52}));
  CHECK(ys == (std::set<double>{3.0 - 0x1p-51, 3.0, 3.0 + 0x1p-51}));
}

