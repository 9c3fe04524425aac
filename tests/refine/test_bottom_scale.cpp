// Refinement at the bottom of double precision (refine/bottom_scale.h): vertices an ulp apart,
// subsegments next to a vertex flush with them, and edges no double can mesh.
#include <cmath>
#include <cstdint>
#include <vector>

#include "harness/check.h"
#include "refine/bottom_scale.h"
#include "refine/refine.h"
#include "refine_fixtures.h"

using namespace deltri;
using namespace refine_test;

namespace {

struct Refined {
  RefineReport report;
  Facts facts;
};

// The Delaunay triangulation of `points`, its hull protected, refined to the angle bound theta.
Refined refined_in_hull(const std::vector<Point>& points, double theta) {
  Mesh m = triangulated(points);
  mark_boundary(m);
  Predicates pred;
  const RefineReport report = refine_mesh(m, pred, quality(theta));
  return {report, facts_of(m)};
}

}  // namespace

TEST(at_bottom_scale_compares_with_the_ulps_of_the_larger_coordinate) {
  const Point p{3.0, -32.0};  // an ulp of 32 is 2^-47
  CHECK(at_bottom_scale(std::pow(63 * 0x1p-47, 2), p));
  CHECK(!at_bottom_scale(std::pow(65 * 0x1p-47, 2), p));
  CHECK(at_bottom_scale(std::pow(95 * 0x1p-47, 2), Point{48.0, 0.0}));  // within a factor of two
  CHECK(!at_bottom_scale(1e-20, Point{0.0, 0.0}));
}

// robustness1.node's pair one ulp apart (both axes have the same ulp there), in a square. The
// coarse precision floor (2^-36 of the coordinates, 65,000 ulps) had left a fan of triangles
// with 1e-13 degree angles around it; at the bottom scale the Steiner points are chosen among
// the doubles, and the mesh is graded down to the pair. (At -q30 three triangles of atan(1/2) =
// 26.57 degrees are left: the choice is greedy, and an earlier point two ulps from the pair
// cannot be undone, although a right isosceles triangle on it would be representable.)
TEST(a_pair_one_ulp_apart_is_meshed_to_the_bound) {
  const double theta = 20.0;
  const auto [r, f] = refined_in_hull({{32, 32}, {64, 32}, {64, 64}, {32, 64},
                                       {41.77377931209348, 55.45235951180828}, {41.77377931209348, 55.45235951180829}},
                                      theta);
  CHECK(f.all_ccw);
  CHECK(f.links_ok);
  CHECK_EQ(f.non_delaunay_edges, std::size_t{0});
  CHECK(f.min_angle >= theta - 1e-9);
  CHECK_EQ(r.bad_triangles_left, std::uint64_t{0});
  CHECK(r.bottom_scale_searches > 0);
  CHECK_EQ(r.hopeless_edges, std::uint64_t{0});
  CHECK(f.triangles < 20000);
}

// robustness2.node's pair one x-ulp apart where a y-ulp is 512 x-ulps: no double makes a
// triangle with it that is not a sliver. Grading the mesh down to it would buy nothing; the
// coarse floor stays, and refinement stops at once around it.
TEST(a_pair_no_double_can_mesh_keeps_the_coarse_floor) {
  const auto [r, f] = refined_in_hull({{-1, -1}, {1, -1}, {1, 1}, {-1, 1},
                                       {0.001739080834353146, 0.7050842932559666}, {0.0017390808343531463, 0.7050842932559666}},
                                      30);
  CHECK(f.all_ccw);
  CHECK(f.links_ok);
  CHECK_EQ(r.hopeless_edges, std::uint64_t{1});
  CHECK(r.stopped_by_guard);
  CHECK(r.bad_triangles_left > 0);
  CHECK(r.interior_steiner + r.segment_steiner < 1000);
}

// From robustness1.node: hull vertex C lies one y-ulp above hull vertex B, 2e-14 off the line
// of hull edge A-B. The rounded midpoint of A-B tilts the half towards B enough to put C on the
// wrong side, so the edge had been locked, and the bottom-scale points placed next to it made
// 1e-27 degree slivers with it. A double near the midpoint that keeps C on the right side splits it.
TEST(a_hull_edge_next_to_a_flush_vertex_is_split_at_a_nearby_double) {
  const auto [r, f] = refined_in_hull({{142.89780553229295, 117.89780553229292}, {146.68071346210041, 121.6807134621004},
                                       {146.68071346210041, 121.68071346210043}, {139.7557862165142, 124.98797731494555},
                                       {150.0, 130.0}, {141.0, 127.5}},
                                      20);
  CHECK(f.all_ccw);
  CHECK(f.boundary_protected);
  CHECK_EQ(r.locked_subsegments, std::uint64_t{0});
  CHECK(f.min_angle >= 20.0 - 1e-9);
}

// BottomScale::creeping_split: a split of a piece over 4096 ulps long is refused when one of its
// halves would join two neighbouring doubles (no double lies between them), and allowed when the
// halves are two lattice steps or more, or the piece is a few ulps long (an ulp cluster).
TEST(creeping_split_refuses_halves_between_neighbouring_doubles_on_long_pieces) {
  const double x = 1.0, up = std::nextafter(x, 2.0), up2 = std::nextafter(up, 2.0);
  const Point A{0.0, 0.0}, B{1.0, 0.0};  // 2^52 ulps of 1 long
  CHECK(BottomScale::creeping_split(Point{x, 0.0}, Point{up2, 0.0}, Point{up, 0.0}, A, B));
  const double up4 = std::nextafter(std::nextafter(up2, 2.0), 2.0);
  CHECK(!BottomScale::creeping_split(Point{x, 0.0}, Point{up4, 0.0}, Point{up2, 0.0}, A, B));
  const Point near_a{1.0, 0.0}, near_b{std::nextafter(std::nextafter(up4, 2.0), 2.0), 0.0};  // 6 ulps long
  CHECK(!BottomScale::creeping_split(Point{x, 0.0}, Point{up2, 0.0}, Point{up, 0.0}, near_a, near_b));
}
