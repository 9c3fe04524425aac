// The doubles near a point, shapes measured on them, and edges no double can give a good
// triangle (geometry/lattice.h).
#include <cmath>
#include <set>
#include <utility>
#include <vector>

#include "geometry/lattice.h"
#include "harness/check.h"

namespace {

using deltri::Point;

double up(double x, int k) {
  for (int i = 0; i < k; ++i) x = std::nextafter(x, HUGE_VAL);
  return x;
}

double sin2(double degrees) {
  const double s = std::sin(degrees * 3.14159265358979323846 / 180.0);
  return s * s;
}

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

TEST(smallest_angle_sine2_of_known_triangles) {
  CHECK_NEAR(deltri::smallest_angle_sine2({0, 0}, {1, 0}, {0.5, std::sqrt(3.0) / 2}), 0.75, 1e-15);
  CHECK_NEAR(deltri::smallest_angle_sine2({0, 0}, {1, 0}, {0, 1}), 0.5, 1e-15);
  CHECK_EQ(deltri::smallest_angle_sine2({0, 0}, {0, 1}, {1, 0}), 0.0);  // clockwise
  CHECK_EQ(deltri::smallest_angle_sine2({0, 0}, {1, 1}, {2, 2}), 0.0);  // collinear
  // One ulp across, far from the origin: the differences and products are exact.
  const double x = 41.77377931209348, y = 55.45235951180828;
  CHECK_EQ(deltri::smallest_angle_sine2({x, y}, {up(x, 1), y}, {x, up(y, 1)}), 0.5);
  // 1 by 2 ulps: the angle opposite the short side is atan(1/2).
  CHECK_NEAR(deltri::smallest_angle_sine2({x, y}, {up(x, 2), y}, {x, up(y, 1)}), 0.2, 1e-15);
}

TEST(hopeless_edge_finds_pairs_no_double_can_mesh) {
  // robustness1.node: a pair one ulp apart where both axes have the same ulp; the right
  // isosceles triangle on it is representable.
  const Point a{41.77377931209348, 55.45235951180828}, b{41.77377931209348, 55.45235951180829};
  CHECK(!deltri::hopeless_edge(a, b, sin2(30)));
  CHECK(!deltri::hopeless_edge(a, b, sin2(44)));
  CHECK(deltri::hopeless_edge(a, b, sin2(46)));
  // robustness1.node: one y-ulp apart where an x-ulp is two y-ulps; the best apex makes
  // atan(1/2) = 26.57 degrees.
  const Point c{137.24095128280055, 112.24095128280054}, d{137.24095128280055, 112.24095128280055};
  CHECK(!deltri::hopeless_edge(c, d, sin2(20)));
  CHECK(!deltri::hopeless_edge(c, d, sin2(26.5)));
  CHECK(deltri::hopeless_edge(c, d, sin2(30)));
  // robustness2.node: one x-ulp apart where a y-ulp is 512 x-ulps: every double within reach
  // lies on the pair's line.
  const Point e{0.001739080834353146, 0.7050842932559666}, f{0.0017390808343531463, 0.7050842932559666};
  CHECK(deltri::hopeless_edge(e, f, sin2(5)));
  // Not proven: an ordinary edge (too many doubles to try), or no angle bound.
  CHECK(!deltri::hopeless_edge({0, 0}, {1, 0}, sin2(30)));
  CHECK(!deltri::hopeless_edge(e, f, 0.0));
}
