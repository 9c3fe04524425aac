// The criteria (refine/criteria.h): the smallest-angle measure, edges no double can give a good
// triangle, and the exact largest-angle test against independent facts.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdlib>
#include <cstdint>
#include <numbers>

#include "geometry/exact_integer.h"
#include "harness/check.h"
#include "refine/criteria.h"

namespace {

using deltri::Point;

double up(double x, int k) {  // k steps up (negative: down)
  for (int i = 0; i < std::abs(k); ++i) x = std::nextafter(x, k > 0 ? HUGE_VAL : -HUGE_VAL);
  return x;
}

double sin2(double degrees) {
  const double s = std::sin(degrees * 3.14159265358979323846 / 180.0);
  return s * s;
}

// A small deterministic generator (the tests need no randomness of quality).
std::uint64_t next(std::uint64_t& state) {
  state = state * 6364136223846793005ULL + 1442695040888963407ULL;
  return state >> 11;
}

}  // namespace

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

// Against the three angles measured one by one (atan2 of cross and dot at each corner): the measure
// is sin^2 of the least of them, whatever the order of the corners' side lengths, so ranking
// triangles by it ranks them by their smallest angles (the vertex relocation search relies on it).
TEST(smallest_angle_sine2_matches_the_least_of_three_angles) {
  std::uint64_t state = 7;
  const auto coordinate = [&] { return static_cast<double>(next(state) % 1000003) / 1000003.0; };
  const auto angle = [](const Point& a, const Point& b, const Point& c) {
    const double ux = b.x - a.x, uy = b.y - a.y, vx = c.x - a.x, vy = c.y - a.y;
    return std::atan2(std::fabs(ux * vy - uy * vx), ux * vx + uy * vy);
  };
  double previous_angle = 0.0, previous_measure = 0.0;
  for (int i = 0; i < 20000; ++i) {
    const Point a{coordinate(), coordinate()}, b{coordinate(), coordinate()}, c{coordinate(), coordinate()};
    const double least = std::min({angle(a, b, c), angle(b, c, a), angle(c, a, b)});
    const double cross = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
    const double measure = deltri::smallest_angle_sine2(a, b, c);
    if (!(cross > 0.0)) {
      CHECK_EQ(measure, 0.0);
      continue;
    }
    CHECK_NEAR(measure, std::sin(least) * std::sin(least), 1e-9);
    if (least > previous_angle + 1e-6) CHECK(measure > previous_measure);
    if (least < previous_angle - 1e-6) CHECK(measure < previous_measure);
    previous_angle = least, previous_measure = measure;
  }
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

// At 90 degrees the test is the sign of the dot product, which exact_integer computes in integers:
// points a few ulps from a right angle, where doubles cannot tell.
TEST(largest_angle_at_90_degrees_is_the_exact_sign_of_the_dot_product) {
  const deltri::LargestAngleBound right(90.0);
  std::uint64_t state = 7;
  int obtuse = 0;
  for (int i = 0; i < 2000; ++i) {
    const double x = 0.1 + 1e-3 * static_cast<double>(next(state) % 1000);
    const Point p{x, 0.3}, a{up(x, static_cast<int>(next(state) % 9) - 4), 1.7};
    const Point b{x + 2.0 + 1e-3 * static_cast<double>(next(state) % 7), up(0.3, static_cast<int>(next(state) % 9) - 4)};
    const bool expected = deltri::exact_integer::dot_sign(a, b, p) < 0;
    CHECK_EQ(deltri::angle_exceeds(p, a, b, right), expected);
    obtuse += expected;
  }
  CHECK(obtuse > 0 && obtuse < 2000);  // both answers occur
  // A right angle exactly does not exceed 90.
  CHECK(!deltri::angle_exceeds({0, 0}, {3, 4}, {-4, 3}, right));
  CHECK(deltri::angle_exceeds({0, 0}, {3, 4}, {-4, 2.9999999999}, right));
}

// Above 90 degrees: angles of known size, the corner found, and near ties decided as the
// integer-exact comparison decides them. cos(120) = -1/2, so the angle at p between (1, 0) and
// (-1, s) is 120 degrees exactly when s = sqrt 3; doubles either side of sqrt 3 are on either side.
TEST(largest_angle_above_90_degrees_near_ties) {
  const deltri::LargestAngleBound bound(120.0);
  CHECK(deltri::angle_exceeds({0, 0}, {1, 0}, {-1, 1.7}, bound));   // 120.5 degrees
  CHECK(!deltri::angle_exceeds({0, 0}, {1, 0}, {-1, 1.8}, bound));  // 119.05 degrees
  // On integer points every quantity is an integer, and cos2() = M 2^(e - 53) exactly, so
  // dot^2 > cos2() |u|^2 |v|^2 is an integer comparison in 128 bits: the test's answer must be it.
  std::uint64_t state = 11;
  int yes = 0;
  for (const double degrees : {100.0, 120.0, 135.0, 150.0}) {
    const deltri::LargestAngleBound b(degrees);
    int e = 0;
    const double m = std::frexp(b.cos2(), &e);
    const auto mantissa = static_cast<__int128>(std::ldexp(m, 53));
    for (int i = 0; i < 3000; ++i) {
      const auto coordinate = [&] { return static_cast<double>(static_cast<int>(next(state) % 33) - 16); };
      const Point p{coordinate(), coordinate()}, a{coordinate(), coordinate()}, q{coordinate(), coordinate()};
      const auto dx = [&](const Point& r) { return static_cast<__int128>(r.x - p.x); };
      const auto dy = [&](const Point& r) { return static_cast<__int128>(r.y - p.y); };
      const __int128 dot = dx(a) * dx(q) + dy(a) * dy(q);
      const __int128 uu = dx(a) * dx(a) + dy(a) * dy(a), vv = dx(q) * dx(q) + dy(q) * dy(q);
      if (uu == 0 || vv == 0) continue;
      const bool expected = dot < 0 && ((dot * dot) << (53 - e)) > mantissa * uu * vv;
      CHECK_EQ(deltri::angle_exceeds(p, a, q, b), expected);
      yes += expected;
    }
  }
  CHECK(yes > 0);
  // The corner is the one with the large angle, whichever corner it is.
  CHECK_EQ(deltri::corner_above({0, 0}, {10, 0}, {5, 1}, deltri::LargestAngleBound(100.0)), 2);
  CHECK_EQ(deltri::corner_above({5, 1}, {0, 0}, {10, 0}, deltri::LargestAngleBound(100.0)), 0);
  CHECK_EQ(deltri::corner_above({5, 1}, {0, 0}, {10, 0}, deltri::LargestAngleBound(170.0)), -1);
  CHECK_EQ(deltri::corner_above({5, 1}, {0, 0}, {10, 0}, deltri::LargestAngleBound()), -1);
}

namespace {

// One triangle a, b, c (counter-clockwise or not) in a mesh of its own.
deltri::Mesh lone_triangle(const Point& a, const Point& b, const Point& c) {
  deltri::Mesh m;
  const deltri::VertexId u = m.add_vertex(a, deltri::VertexKind::Input);
  const deltri::VertexId v = m.add_vertex(b, deltri::VertexKind::Input);
  const deltri::VertexId w = m.add_vertex(c, deltri::VertexKind::Input);
  m.add_triangle(u, v, w);
  return m;
}

}  // namespace

// Calls check(mesh, rules, near) for 60,000 triangles, each alone in a mesh of its own under rules
// with a quick verdict: random triangles, and triangles whose smallest angle lies within a few ulps
// to 1e-9 (relative) of the bound, so that the quotient the full test rounds sits at 1 (near: within
// 1e-12 of it); with an area bound at the triangle's own area, one ulp either side, or none.
template <class Check>
void for_quick_verdict_triangles(Check&& check) {
  using namespace deltri;
  std::uint64_t state = 11;
  const auto unit = [&] { return static_cast<double>(next(state) % 1000003) / 1000003.0; };
  for (const double theta : {20.0, 28.6, 30.0, 33.0, 34.0}) {
    const AngleBound bound(theta);
    const double phi0 = theta * std::numbers::pi / 180.0;
    for (int i = 0; i < 12000; ++i) {
      Point a{unit(), unit()}, b{unit(), unit()}, c{unit(), unit()};
      if (i % 2 == 1) {  // the smallest angle, at a, within about 1e-9 of the bound
        const double scale = std::ldexp(1.0 + unit(), static_cast<int>(next(state) % 40) - 20);
        const double turn = 2 * std::numbers::pi * unit();
        const double phi = phi0 * (1.0 + (unit() - 0.5) * (i % 4 == 1 ? 1e-9 : 1e-14));
        const double longer = 1.0 + 0.3 * unit();
        a = {1000 * unit() - 500, 1000 * unit() - 500};
        b = {a.x + scale * std::cos(turn), a.y + scale * std::sin(turn)};
        c = {a.x + scale * longer * std::cos(turn + phi), a.y + scale * longer * std::sin(turn + phi)};
      }
      const Mesh m = lone_triangle(a, b, c);
      const double area = 0.5 * side_measures(m, TriangleId{0}).twice_area;
      const double max_area = i % 3 == 0 ? 0.0 : up(area, i % 3 == 1 ? 1 : -1);
      const Criteria rules{bound, SizeBounds{max_area, false, 0.0}};
      REQUIRE(has_quick_verdict(rules));
      const double ratio = assess_triangle(m, TriangleId{0}, rules).shape.ratio2_over_bound2;
      check(m, rules, std::fabs(ratio - 1.0) < 1e-12);
    }
  }
}

// surely_good (the refinement's quick "good" verdict) against the full assessment, the verdict
// refinement acts on: whatever it calls good must be neither skinny nor too large there. A verdict
// with any slack above the rounded quotient (comparing x against y (1 + 1e-13), say) calls some of
// the near ties good that the full test calls skinny. The counts of near ties on either side make
// sure the test reaches them.
TEST(surely_good_never_contradicts_the_full_assessment) {
  using namespace deltri;
  int good = 0, good_near = 0, bad_near = 0, area_near = 0;
  for_quick_verdict_triangles([&](const Mesh& m, const Criteria& rules, bool near) {
    const Assessment full = assess_triangle(m, TriangleId{0}, rules);
    if (!surely_good(side_measures(m, TriangleId{0}), rules)) {
      bad_near += near && !full.skinny;  // a near tie left to the full test
      return;
    }
    CHECK(!full.bad());
    ++good;
    good_near += near;
    area_near += rules.size.max_area > 0.0 && rules.size.max_area > full.shape.area;
  });
  CHECK(good > 10000);
  CHECK(good_near > 100);
  CHECK(bad_near > 100);
  CHECK(area_near > 1000);
}

// queue_badness (the queue's verdict on a triangle no angle of which lies between two subsegments)
// against the full assessment: bad exactly where it is, skinny exactly where it is, and the same
// doubles for the queue's keys, bit for bit, on the same triangles, flat and clockwise ones included.
TEST(queue_badness_is_the_full_assessment) {
  using namespace deltri;
  int bad = 0, skinny_near = 0, good_near = 0, only_large = 0;
  const auto agree = [&](const Mesh& m, const Criteria& rules, bool near) {
    const Assessment full = assess_triangle(m, TriangleId{0}, rules);
    Badness why;
    const bool verdict = queue_badness(side_measures(m, TriangleId{0}), rules, why);
    CHECK_EQ(verdict, full.bad());
    skinny_near += near && full.skinny;
    good_near += near && !full.bad();
    if (!verdict) return;
    ++bad;
    only_large += !full.skinny;
    CHECK_EQ(why.skinny, full.skinny);
    CHECK(std::bit_cast<std::uint64_t>(why.ratio2_over_bound2) == std::bit_cast<std::uint64_t>(full.shape.ratio2_over_bound2));
    CHECK(std::bit_cast<std::uint64_t>(why.shortest2) == std::bit_cast<std::uint64_t>(full.shape.shortest_length2));
  };
  for_quick_verdict_triangles(agree);
  const Criteria rules{AngleBound(30), SizeBounds{0.25, false, 0.0}};
  agree(lone_triangle({0, 0}, {0, 1}, {1, 0}), rules, false);  // clockwise
  agree(lone_triangle({0, 0}, {1, 1}, {2, 2}), rules, false);  // flat
  CHECK(bad > 10000);
  CHECK(skinny_near > 100);
  CHECK(good_near > 100);
  CHECK(only_large > 1000);
}

// Rules with anything beyond the angle bound and -a's one area bound have no quick verdict.
TEST(quick_verdict_only_for_the_angle_and_one_area_bound) {
  using namespace deltri;
  CHECK(has_quick_verdict(Criteria{AngleBound(30), SizeBounds{0.5, false, 0.0}}));
  CHECK(!has_quick_verdict(Criteria{AngleBound(30), SizeBounds{0.0, true, 0.0}}));
  CHECK(!has_quick_verdict(Criteria{AngleBound(30), SizeBounds{0.0, false, 2.0}}));
  CHECK(!has_quick_verdict(Criteria{AngleBound(30), SizeBounds{}, LargestAngleBound(100)}));
}
