// The pieces of the Terminator, each against facts worked out by hand.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "geometry/constructions.h"
#include "harness/check.h"
#include "harness/id_literals.h"
#include "mesh/internal.h"
#include "mesh/mesh_checks.h"
#include "mesh/operations.h"
#include "mesh/topology_writer.h"
#include "refine/criteria.h"
#include "refine/candidate_probe.h"
#include "refine/clusters.h"
#include "refine/concentric_shells.h"
#include "refine/edge_finder.h"
#include "refine/encroached.h"
#include "refine/encroached_queue.h"
#include "refine/mirrored_split.h"
#include "refine/split_permitted.h"
#include "refine/steiner_point.h"
#include "refine/termination_guard.h"
#include "refine_fixtures.h"

using namespace deltri;
using namespace refine_test;

namespace {
constexpr double kPi = std::numbers::pi;
double rad(double deg) { return deg * kPi / 180.0; }
Criteria rules_of(AngleBound angle, SizeBounds size) { return {angle, size}; }
}  // namespace

TEST(subsegment_encroached_by_either_apex) {
  // Square with a vertex just above the bottom side's midpoint.
  Mesh m = triangulated({{0, 0}, {2, 0}, {2, 2}, {0, 2}, {1, 0.3}});
  mark_boundary(m);
  Predicates pred;
  int encroached = 0;
  for (EdgeRef e{0}; e < m.corner.size(); ++e)
    if (m.subseg.has(e) && is_encroached(m, pred, e, EncroachRule::circle())) {
      ++encroached;
      CHECK_EQ(m.point(m.org(e)).y + m.point(m.dest(e)).y, 0.0);  // the bottom side only
    }
  CHECK_EQ(encroached, 1);
}

// Stale queue entries: a flip rewrites the two slots beside an edge, so entries made before it no
// longer match them; a rotated entry still matches; a killed slot matches nothing.
TEST(queue_entries_go_stale_when_their_slot_changes) {
  Mesh m = triangulated({{0, 0}, {3, 0}, {3.2, 2}, {0.1, 2.1}, {1.5, 0.9}});
  std::vector<QueuedTriangle> entries;
  for (TriangleId t{0}; t < m.triangle_slots(); ++t)
    if (m.is_live(t)) entries.push_back({t, m.corner[edge_of(t, 0)], m.corner[edge_of(t, 1)], m.corner[edge_of(t, 2)]});
  for (const QueuedTriangle& e : entries) {
    CHECK(is_current(m, e));
    CHECK(is_current(m, {e.triangle, e.b, e.c, e.a}));   // the same triangle, another rotation
    CHECK(!is_current(m, {e.triangle, e.a, e.b, VertexId{9999}}));  // another third vertex
  }
  // Flip one interior edge whose quadrilateral is convex; exactly its two slots go stale.
  Predicates pred;
  EdgeRef flipped = kNone;
  for (EdgeRef e{0}; e < m.corner.size() && flipped == kNone; ++e) {
    const EdgeRef twin = m.link[e];
    if (m.corner[e] == kNone || twin == kNone) continue;
    const Point &a = m.point(m.org(e)), &b = m.point(m.dest(e));
    const Point &c = m.point(m.apex(e)), &d = m.point(m.apex(twin));
    if (pred.orient2d(c, d, b) > 0 && pred.orient2d(d, c, a) > 0) flipped = e;
  }
  REQUIRE(flipped != kNone);
  const TriangleId t1 = triangle_of(flipped), t2 = triangle_of(m.link[flipped]);
  flip(m, flipped);
  for (const QueuedTriangle& e : entries) CHECK_EQ(is_current(m, e), e.triangle != t1 && e.triangle != t2);
  const QueuedTriangle survivor = entries[0].triangle != t1 && entries[0].triangle != t2 ? entries[0] : entries.back();
  REQUIRE(is_current(m, survivor));
  m.kill_triangle(survivor.triangle);
  CHECK(!is_current(m, survivor));
  CHECK(!is_current(m, {TriangleId{m.triangle_slots() + 5}, survivor.a, survivor.b, survivor.c}));  // beyond the mesh
}

TEST(bad_triangle_test) {
  // Isosceles triangle with apex angle 20 degrees: skinny at 30, fine at 19.
  const double h = 1.0 / std::tan(rad(10));
  Mesh m = triangulated({{-1, 0}, {1, 0}, {0, h}});
  const Criteria q30 = rules_of(AngleBound(30), {0, false, 0});
  const Criteria q19 = rules_of(AngleBound(19), {0, false, 0});
  CHECK(assess_triangle(m, 0_t, q30).skinny);
  CHECK(!assess_triangle(m, 0_t, q19).skinny);
  // (r / B)^2: r / l = 1 / (2 sin 20deg), B = 1 / (2 sin 30deg).
  const double expected = std::pow(std::sin(rad(30)) / std::sin(rad(20)), 2);
  CHECK_NEAR(assess_triangle(m, 0_t, q30).shape.ratio2_over_bound2, expected, 1e-12);
  // Size tests.
  CHECK(assess_triangle(m, 0_t, rules_of(AngleBound(), {h - 0.01, false, 0})).too_large);
  CHECK(!assess_triangle(m, 0_t, rules_of(AngleBound(), {h + 0.01, false, 0})).too_large);
  CHECK(assess_triangle(m, 0_t, rules_of(AngleBound(), {0, false, 5.0})).too_large);
  m.area_bound.assign(1, 1.0);
  CHECK(assess_triangle(m, 0_t, rules_of(AngleBound(), {0, true, 0})).too_large);
  // How far over: the area h against bounds of h / 4 and 2h, the legs' squared length 1 + h^2
  // against an edge bound of 2; the smallest area bound that applies counts.
  const TriangleShape shape = measure_triangle(m, 0_t, 0.0);
  CHECK_NEAR(size_excess(m, 0_t, shape, rules_of(AngleBound(), {h / 4, false, 0})), 4.0, 1e-12);
  CHECK_NEAR(size_excess(m, 0_t, shape, rules_of(AngleBound(), {2 * h, false, 0})), 0.5, 1e-12);
  m.area_bound.assign(1, h / 8);
  CHECK_NEAR(size_excess(m, 0_t, shape, rules_of(AngleBound(), {h / 4, true, 0})), 8.0, 1e-12);
  CHECK_NEAR(size_excess(m, 0_t, shape, rules_of(AngleBound(), {0, false, 2.0})), (1 + h * h) / 4, 1e-12);
  CHECK(!assess_triangle(m, 0_t, rules_of(AngleBound(), {0, false, 0})).too_large);
}

TEST(small_angle_between_two_subsegments_is_not_split) {
  // Two triangles: the thin one's smallest angle (at the origin) lies between two subsegments.
  Mesh m = triangulated({{0, 0}, {1, 0}, {1, 0.1}, {0, 1}});
  mark_boundary(m);
  CHECK(mark_segment(m, 0, 2));
  const Criteria q = rules_of(AngleBound(20), {0, false, 0});
  for (TriangleId t{0}; t < m.triangle_slots(); ++t) {
    const Assessment a = assess_triangle(m, t, q);
    if (min_angle_deg(m, t) < 10) {
      CHECK(a.shape.ratio2_over_bound2 > 1.0);
      CHECK(!a.skinny);
    }
  }
  detail::subseg_slots(m).assign(m.subseg.size());  // without the subsegments it is skinny
  bool found = false;
  for (TriangleId t{0}; t < m.triangle_slots(); ++t) found = found || assess_triangle(m, t, q).skinny;
  CHECK(found);
}

TEST(concentric_shells_split_points) {
  for (double length : {0.3, 1.0, 1.5, 2.9, 3.0, 7.77, 1000.0}) {
    const double r = shell_radius(length);
    CHECK(r >= length / 3.0 && r < 2.0 * length / 3.0);
    CHECK_EQ(std::exp2(std::round(std::log2(r))), r);
  }
  const Point a{0, 0}, b{3, 0};
  CHECK(shell_split_point(a, b, false, false) == (Point{1.5, 0}));
  CHECK(shell_split_point(a, b, true, false) == (Point{1, 0}));   // radius 1 from a
  CHECK(shell_split_point(a, b, false, true) == (Point{2, 0}));   // radius 1 from b
  CHECK(shell_split_point(a, {4, 0}, true, true) == (Point{2, 0}));  // power of two: the midpoint
}

// A fan from the origin: spokes to (1,0), (cos 20, sin 20), (cos 40, sin 40) and (0, 1) ... the
// last 50 degrees away, so the cluster at the origin holds three subsegments.
Mesh cluster_mesh() {
  std::vector<Point> pts{{0, 0}};
  for (double d : {0.0, 20.0, 40.0, 90.0}) pts.push_back({std::cos(rad(d)), std::sin(rad(d))});
  Mesh m = triangulated(pts);
  mark_boundary(m);
  mark_segment(m, 0, 2);
  mark_segment(m, 0, 3);
  return m;
}

EdgeRef edge_between(const Mesh& m, std::uint32_t a, std::uint32_t b) {
  for (EdgeRef e{0}; e < m.corner.size(); ++e)
    if (m.corner[e] != kNone && m.org(e) == a && m.dest(e) == b) return e;
  return kNone;
}

// Shells only where two subsegments follow each other at less than 90 degrees inside the domain:
// the corners of a square (90) and of a regular hexagon (120) split at midpoints, those of an
// equilateral triangle (60) and the origin of the fan (20 between spokes) on shells.
TEST(shells_only_at_acute_apices) {
  const auto boundary_of = [](std::vector<Point> pts) {
    Mesh m = triangulated(pts);
    mark_boundary(m);
    return m;
  };
  const SegmentApices square(boundary_of({{0, 0}, {1, 0}, {1, 1}, {0, 1}}));
  std::vector<Point> hexagon, equilateral;
  for (int k = 0; k < 6; ++k) hexagon.push_back({std::cos(rad(60.0 * k)), std::sin(rad(60.0 * k))});
  for (int k = 0; k < 3; ++k) equilateral.push_back({std::cos(rad(120.0 * k)), std::sin(rad(120.0 * k))});
  const SegmentApices hex(boundary_of(hexagon));
  const SegmentApices tri(boundary_of(equilateral));
  for (VertexId v{0}; v < 4; ++v) CHECK(square.is_apex(v) && !square.uses_shells(v));
  for (VertexId v{0}; v < 6; ++v) CHECK(hex.is_apex(v) && !hex.uses_shells(v));
  for (VertexId v{0}; v < 3; ++v) CHECK(tri.uses_shells(v));
  const SegmentApices fan(cluster_mesh());
  CHECK(fan.uses_shells(0_v));
}

// Vertex 0 is the corner of a hull triangle with angle theta there, inside which a fan of points
// at radius 0.5 gives the corner many triangles. Within about 1e-9 radians of 90 degrees the wedge
// is summed triangle by triangle; beyond, it is read off the two subsegments' directions. Either
// way the shell follows the angle: 90 degrees and less than 1e-12 under it count as right.
TEST(shells_at_fanned_corners_follow_the_angle_on_both_sides_of_ninety) {
  const auto corner = [](double theta) {
    std::vector<Point> pts{{0, 0}, {1, 0}, {std::cos(theta), std::sin(theta)}};
    for (int k = 1; k < 12; ++k) pts.push_back({0.5 * std::cos(theta * k / 12), 0.5 * std::sin(theta * k / 12)});
    Mesh m = triangulated(pts);
    mark_boundary(m);
    return SegmentApices(m).uses_shells(0_v);
  };
  const double right = std::numbers::pi / 2;
  CHECK(corner(rad(60)));
  CHECK(corner(right - 3e-9));
  CHECK(corner(right - 1e-10));
  CHECK(!corner(right - 1e-13));
  CHECK(!corner(right));
  CHECK(!corner(right + 1e-10));
  CHECK(!corner(right + 3e-9));
  CHECK(!corner(rad(120)));
}

TEST(clusters_gather_subsegments_within_sixty_degrees) {
  Mesh m = cluster_mesh();
  const SegmentApices apices(m);
  CHECK(apices.is_apex(0_v));
  CHECK(apices.is_apex(1_v));  // end of the boundary and of nothing else, but two boundary sides
  const EdgeRef spoke = edge_between(m, 0, 2);
  REQUIRE(spoke != kNone);
  const Cluster c = subsegment_cluster(m, spoke);
  CHECK_EQ(c.members.size(), std::size_t{3});  // 0, 20 and 40 degrees; 90 is 50 away from 40?
  CHECK_NEAR(c.min_separation, rad(20), 1e-12);
}

// A 3-degree wedge at vertex 0 between pieces 0-1 (along x) and 0-2; vertex 3 stands for a split
// point on 0-2 at distance 0.45 from 0, the apex of the triangle beside subsegment 0-1.
TEST(mirrored_split_lines_up_with_the_vertex_across_the_wedge) {
  const Point dir{std::cos(rad(3)), std::sin(rad(3))};
  Mesh m = triangulated({{0, 0}, {1, 0}, {1.2 * dir.x, 1.2 * dir.y}, {0.45 * dir.x, 0.45 * dir.y}});
  const EdgeRef s = edge_between(m, 0, 1) != kNone ? edge_between(m, 0, 1) : edge_between(m, 1, 0);
  REQUIRE(s != kNone);
  REQUIRE(m.apex(s) == 3 || (m.link[s] != kNone && m.apex(m.link[s]) == 3));
  SegmentPieces pieces;
  pieces.splits = {{3_v, {0_v, 2_v}}};
  Point p{-1, -1};
  CHECK(mirrored_split_point(m, s, {0_v, 1_v}, pieces, p));
  CHECK_NEAR(p.x, 0.45, 1e-15);
  CHECK_EQ(p.y, 0.0);
  // Not across the wedge: a vertex of the same piece, or one that is on no piece.
  pieces.splits = {{3_v, {1_v, 0_v}}};
  CHECK(!mirrored_split_point(m, s, {0_v, 1_v}, pieces, p));
  pieces.splits.clear();
  CHECK(!mirrored_split_point(m, s, {0_v, 1_v}, pieces, p));
  // Vertex 3 as the far end of an initial piece 0-3: the same point.
  pieces.set_initial({SegmentPieces::piece_key(0_v, 1_v), SegmentPieces::piece_key(3_v, 0_v)});
  p = {-1, -1};
  CHECK(mirrored_split_point(m, s, {0_v, 1_v}, pieces, p));
  CHECK_NEAR(p.x, 0.45, 1e-15);
  // Outside the middle third of s (at 0.2 of it): the shells or the midpoint decide instead.
  pieces.splits = {{3_v, {0_v, 2_v}}};
  m.points[3] = {0.2 * dir.x, 0.2 * dir.y};
  CHECK(!mirrored_split_point(m, s, {0_v, 1_v}, pieces, p));
}

TEST(split_permitted_follows_figure_38) {
  Mesh m = cluster_mesh();
  const SegmentApices apices(m);
  const EdgeRef spoke = edge_between(m, 0, 2);  // length 1, a power of two, in one cluster
  // r_min = 1 * sin(10 degrees) ~ 0.1736.
  CHECK(split_permitted(m, apices, spoke, 0.17));
  CHECK(!split_permitted(m, apices, spoke, 0.18));
  // A subsegment whose length is not a power of two may always be split.
  Mesh n = cluster_mesh();
  n.points[2] = {0.9 * std::cos(rad(20)), 0.9 * std::sin(rad(20))};
  CHECK(split_permitted(n, SegmentApices(n), edge_between(n, 0, 2), 10.0));
  CHECK(is_power_of_two_length(0.25 * (1 + 1e-6)));
  CHECK(!is_power_of_two_length(0.3));
}

TEST(off_center_is_nearer_than_circumcenter_on_the_bisector) {
  const double h = 1.0 / std::tan(rad(5));  // 10 degree apex: circumcentre at y ~ 5.67
  Mesh m = triangulated({{-1, 0}, {1, 0}, {0, h}});
  const TriangleShape s = measure_triangle(m, 0_t, 0.25);
  const Point centre = off_center(m.point(0_v), m.point(1_v), m.point(2_v), 0.0);
  const Point off = steiner_point(m, s.shortest, AngleBound(30).off_center_factor());
  CHECK_NEAR(off.x, 0.0, 1e-12);
  CHECK_NEAR(off.y, 0.475 / std::tan(rad(15)) * 2.0, 1e-12);  // from the midpoint of the base
  CHECK(off.y < centre.y);
  CHECK(steiner_point(m, s.shortest, 0.0) == centre);
  // At a 20 degree apex the off-centre (y ~ 3.55) would lie beyond the circumcentre (y ~ 2.75).
  Mesh wide = triangulated({{-1, 0}, {1, 0}, {0, 1.0 / std::tan(rad(10))}});
  const TriangleShape w = measure_triangle(wide, 0_t, 0.25);
  CHECK(steiner_point(wide, w.shortest, AngleBound(30).off_center_factor()) ==
        off_center(wide.point(0_v), wide.point(1_v), wide.point(2_v), 0.0));
  // A triangle near the bound keeps its circumcentre.
  Mesh fine = triangulated({{0, 0}, {1, 0}, {0.5, 0.8}});
  const TriangleShape f = measure_triangle(fine, 0_t, 0.25);
  CHECK(steiner_point(fine, f.shortest, AngleBound(30).off_center_factor()) ==
        off_center(fine.point(0_v), fine.point(1_v), fine.point(2_v), 0.0));
}

TEST(probe_leaves_the_mesh_untouched_and_finds_encroachment) {
  // A flat triangle on the bottom side: its circumcentre lies below the square.
  Mesh m = triangulated({{0, 0}, {4, 0}, {4, 4}, {0, 4}, {2, 0.2}});
  mark_boundary(m);
  Predicates pred;
  CavityMarks marks;
  const Snapshot before(m);
  const auto all = [](EdgeRef) { return true; };
  for (TriangleId t{0}; t < m.triangle_slots(); ++t) {
    const Point c = off_center(m.point(m.corner[edge_of(t, 0)]), m.point(m.corner[edge_of(t, 1)]),
                               m.point(m.corner[edge_of(t, 2)]), 0.0);
    const Probe p = probe_candidate(m, pred, t, c, EncroachRule::lens(30), marks, all);
    if (c.y < 0) {
      CHECK(p.status == ProbeStatus::Encroaches);
      CHECK(p.blocked);
      REQUIRE(p.encroached.size() == 1);
      CHECK_EQ(m.point(m.org(p.encroached[0])).y, 0.0);
    }
  }
  CHECK(Snapshot(m) == before);
  // A point in the middle is clear; its insertion radius is its distance to the nearest vertex
  // of its cavity.
  const Probe p = probe_candidate(m, pred, 0_t, {2, 2}, EncroachRule::lens(30), marks, all);
  CHECK(p.status == ProbeStatus::Clear);
  CHECK_NEAR(p.insertion_radius, 1.8, 1e-12);
}

TEST(encroached_queue_is_fifo) {
  EncroachedQueue q;
  q.push({3_e, 1_v, 2_v});
  q.push({6_e, 4_v, 5_v});
  CHECK_EQ(q.size(), std::size_t{2});
  CHECK_EQ(q.pop().edge, 3u);
  CHECK_EQ(q.pop().edge, 6u);
  CHECK(q.empty());
}

TEST(edge_finder_survives_flips) {
  Mesh m = triangulated({{0, 0}, {2, 0}, {2, 1}, {0, 1}, {1, 0.5}});
  EdgeFinder finder(m);
  // Flip every flippable interior edge once; the finder must still find each remaining edge.
  for (EdgeRef e{0}; e < m.corner.size(); ++e) {
    const EdgeRef f = m.link[e];
    if (f == kNone || f < e) continue;
    Predicates pred;
    const Point& a = m.point(m.org(e));
    const Point& b = m.point(m.dest(e));
    const Point& c = m.point(m.apex(e));
    const Point& d = m.point(m.apex(f));
    if (pred.orient2d(c, d, b) > 0 && pred.orient2d(d, c, a) > 0) {
      flip(m, e);
      break;
    }
  }
  for (EdgeRef e{0}; e < m.corner.size(); ++e) {
    const EdgeRef found = finder.find(m, m.org(e), m.dest(e));
    REQUIRE(found != kNone);
    CHECK((m.org(found) == m.org(e) && m.dest(found) == m.dest(e)) ||
          (m.org(found) == m.dest(e) && m.dest(found) == m.org(e)));
  }
  CHECK_EQ(finder.find(m, 0_v, 2_v) == kNone, edge_between(m, 0, 2) == kNone && edge_between(m, 2, 0) == kNone);
}

TEST(guard_features_and_floor) {
  Mesh m = triangulated({{0, 0}, {4, 0}, {4, 4}, {0, 4}, {2, 0.5}});
  mark_boundary(m);
  const std::vector<double> f = initial_feature_sizes(m);
  CHECK_NEAR(f[4], 0.5, 1e-15);  // its height over the bottom subsegment
  CHECK_NEAR(f[2], 4.0, 1e-15);
  CHECK_NEAR(guard_floor(1.0, 0.0), std::ldexp(1.0, -kGuardOctaves), 0.0);
  // Only the square's 90-degree corners: no scaling.
  CHECK_NEAR(smallest_input_angle(m), rad(90), 1e-12);
  CHECK_EQ(angle_scale(smallest_input_angle(m)), 1.0);
  // A spoke 20 degrees above the base, meeting it at the origin.
  Mesh fan = triangulated({{0, 0}, {1, 0}, {std::cos(rad(20)), std::sin(rad(20))}, {0, 1}});
  mark_boundary(fan);
  REQUIRE(mark_segment(fan, 0, 2) || mark_segment(fan, 2, 0));
  CHECK_NEAR(smallest_input_angle(fan), rad(20), 1e-12);
  CHECK_NEAR(angle_scale(rad(20)), 2 * std::sin(rad(10)), 1e-15);
  CHECK_EQ(angle_scale(rad(60)), 1.0);
  CHECK_NEAR(guard_floor(1.0, 0.5), std::ldexp(0.5, -kGuardOctaves), 0.0);
}

// The guard's Steiner cap: kCapPerWork per unit of feature work, kCapPerVertex per vertex, plus four
// times the triangles the size bounds ask for; the square's feature work by hand. Its two triangles
// (0,0),(1,0),(1,1) and (0,0),(1,1),(0,1): every corner's feature size is 1 (shortest edge, height
// over the opposite side); each triangle adds its area 1/2 over 1^2, and per edge half its length
// over max(height across, 1) = 1, so 1 + 1 + sqrt(2)/2; the two corners on the diagonal grade
// over log2(1 + sqrt(2)) octaves, the other two over log2(2) = 1.
TEST(steiner_cap_counts_feature_work_vertices_and_size_bounds) {
  Mesh m = refine_test::unit_square();
  const double work = 2 * 0.5 + 2 * (1.0 + std::sqrt(2.0) / 2) + 2 * std::log2(1 + std::sqrt(2.0)) + 2;
  CHECK_NEAR(feature_work(m), work, 1e-12);
  const auto cap = [&](double wanted) {
    return static_cast<std::uint64_t>(kCapPerWork * work + 4.0 * kCapPerVertex + 4.0 * wanted);
  };
  CHECK_EQ(steiner_cap(m, {}), cap(0));
  CHECK_EQ(steiner_cap(m, {0.01, false, 0.0}), cap(100));
  // An edge bound L asks for area / (sqrt(3)/4 L^2) triangles: 1 / (0.4330127 * 0.01) = 230.94.
  CHECK_EQ(steiner_cap(m, {0.0, false, 0.1}), cap(1 / (std::sqrt(3.0) / 4 * 0.01)));
  m.area_bound.assign(m.triangle_slots(), 0.5);  // per-triangle bounds of 0.5 on two triangles of 0.5
  CHECK_EQ(steiner_cap(m, {0.0, true, 0.0}), cap(2));
  CHECK_EQ(steiner_cap(m, {0.25, true, 0.0}), cap(4));
}

// The integral of 1/lfs^2 over a strip L x h grows as L / h (lfs is h/2 across the middle): the
// estimate must follow it within a small factor for every aspect ratio, or the cap would cut off a
// thin domain (a 1 x 3.3e-5 rectangle needs 65,536 triangles at -q30) or let runaway refinement of
// a wide one go far.
TEST(feature_work_follows_the_strip_integral) {
  for (double h : {1e-2, 1e-4, 1e-6}) {
    Mesh m = triangulated({{0, 0}, {1, 0}, {1, h}, {0, h}});
    mark_boundary(m);
    const double work = feature_work(m);
    CHECK(work > 1.0 / h && work < 4.0 / h);
  }
}

// Memory: what fits beside the mesh, at kBytesPerSteiner each.
TEST(memory_cap_fits_the_budget) {
  const Mesh m = refine_test::unit_square();
  CHECK_EQ(memory_cap(m.triangle_slots(), 0.0), UINT64_MAX);
  const double used = kBytesPerTriangle * m.triangle_slots();
  CHECK_EQ(memory_cap(m.triangle_slots(), used + 1000 * kBytesPerSteiner), std::uint64_t{1000});
  CHECK_EQ(memory_cap(m.triangle_slots(), used / 2), std::uint64_t{0});
}

namespace {

// The area bound of the live triangle holding the directed edge a->b, or -1.
double bound_on_edge(const Mesh& m, VertexId a, VertexId b) {
  const EdgeRef e = edge_between(m, a, b);
  return e == kNone ? -1.0 : m.area_bound[triangle_of(e)];
}

}  // namespace

// The fan that replaces a probed cavity is the triangulation Lawson's flips reach, triangle for
// triangle, and each new triangle takes the data of the cavity triangle whose boundary edge it
// stands on. Random points, the hull and a few inner edges as subsegments, random probes.
TEST(known_cavity_fan_matches_lawson_flips) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Point> pts;
  for (int i = 0; i < 300; ++i) pts.push_back({u(rng), u(rng)});
  Mesh m = triangulated(pts);
  mark_boundary(m);
  for (EdgeRef e{0}; e < m.corner.size(); e = EdgeRef{e + 37})
    if (m.corner[e] != kNone && m.link[e] != kNone && !m.subseg.has(e)) mark_segment(m, m.org(e), m.dest(e));
  m.area_bound.resize(m.triangle_slots());
  for (TriangleId t{0}; t < m.triangle_slots(); ++t) m.area_bound[t] = 1.0 + t;
  Predicates pred;
  CavityMarks marks;
  int filled = 0, tried = 0;
  for (int k = 0; k < 400; ++k) {
    const Point c{u(rng), u(rng)};
    const Location at = locate(m, pred, c, 0_e);
    if (at.status != LocateStatus::InTriangle) continue;
    const TriangleId seed = triangle_of(at.edge);
    const double nearest2 = detail::cavity_of(m, pred, {&seed, 1}, c, marks);
    ++tried;
    Mesh flips = m, fan = m;
    const VertexId v = flips.add_vertex(c, VertexKind::Free);
    fan.add_vertex(c, VertexKind::Free);
    REQUIRE(insert_vertex(flips, pred, v, at.edge, false).status == InsertStatus::Inserted);
    // The search's nearest cavity vertex is the nearest vertex that the insertion joins to c.
    double joined2 = HUGE_VAL;
    for (EdgeRef e{0}; e < flips.corner.size(); ++e)
      if (flips.corner[e] == v) joined2 = std::min(joined2, squared_distance(c, flips.point(flips.dest(e))));
    CHECK_EQ(nearest2, joined2);
    const EdgeRef out = detail::fill_star(fan, pred, v, marks.marked());
    if (out == kNone) {
      CHECK(meshcheck::triangle_set(fan) == meshcheck::triangle_set(m));  // refused: nothing changed
      continue;
    }
    ++filled;
    CHECK_EQ(fan.org(out), v);
    CHECK(meshcheck::triangle_set(fan) == meshcheck::triangle_set(flips));
    const Facts facts = facts_of(fan);
    CHECK(facts.all_ccw && facts.links_ok && facts.subsegments_symmetric);
    for (EdgeRef e{0}; e < fan.corner.size(); ++e) {
      if (fan.corner[e] == kNone || fan.corner[lprev(e)] != v) continue;
      CHECK_EQ(fan.area_bound[triangle_of(e)], bound_on_edge(m, fan.org(e), fan.dest(e)));
      if (fan.link[e] != kNone) CHECK_EQ(fan.subseg[e], m.subseg[edge_between(m, fan.org(e), fan.dest(e))]);
    }
  }
  CHECK(tried > 300);
  CHECK(filled > tried * 9 / 10);  // refusals are for cavities that are not disks: rare
}

// A subsegment with an obtuse apex: the point beyond it lies in the triangle's circle but sees the
// subsegment from outside, so no fan may stand on it.
TEST(known_cavity_fan_refuses_a_subsegment_seen_from_outside) {
  // The circle through (0,0), (4,0) and (2,0.5) has centre (2,-3.75) and radius 4.25.
  Mesh m = triangulated({{0, 0}, {4, 0}, {2, 0.5}, {2, -9}});
  mark_boundary(m);
  REQUIRE(mark_segment(m, 0, 1));
  const EdgeRef base = edge_between(m, 0, 1);
  REQUIRE(base != kNone && m.apex(base) == 2);
  const TriangleId t = triangle_of(base);
  const EdgeRef boundary[3] = {edge_of(t, 0), edge_of(t, 1), edge_of(t, 2)};
  KnownCavity cavity;
  cavity.list = &t, cavity.count = 1, cavity.triangles = 1, cavity.boundary = boundary;
  Predicates pred;
  const auto before = meshcheck::triangle_set(m);
  const VertexId v = m.add_vertex({2, -0.1}, VertexKind::Free);  // in the circle through 0, 1 and 2
  CHECK(detail::fill_star(m, pred, v, cavity) == kNone);
  CHECK(meshcheck::triangle_set(m) == before);
  cavity.triangles = 2;  // a count that does not fit the boundary: not a disk
  const VertexId w = m.add_vertex({2, 0.2}, VertexKind::Free);
  CHECK(detail::fill_star(m, pred, w, cavity) == kNone);
  cavity.triangles = 1;
  CHECK(detail::fill_star(m, pred, w, cavity) != kNone);  // inside: the fan of three
  CHECK_EQ(m.live_triangles(), 4u);
}

// The Delaunay triangulation of an n x n grid of points, each moved by up to 0.3 on each axis
// (a fixed seed), its hull edges marked as boundary.
static Mesh jittered_grid(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> jitter(-0.3, 0.3);
  std::vector<Point> points;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) points.push_back({i + jitter(rng), j + jitter(rng)});
  Mesh m = triangulated(points);
  mark_boundary(m);
  return m;
}

// The locally optimal point's search on a jittered grid (every triangle's shortest edge, -q33):
// the point it returns is either the off-centre or one that is admissible (exactly inside the
// triangle's circumcircle, triangle pqx at 33 degrees or more by trigonometry), and every triangle
// of the mesh whose circumcircle holds it (exact incircle) was gathered, so its star was judged
// whole. The search gathers only the triangles whose circumcircles may meet the petal: a few
// dozen, where the disk of the petal's reach held the cap of 96 (docs/benchmarks.md, issue 45).
TEST(petal_search_gathers_the_whole_cavity_and_little_else) {
  Mesh m = jittered_grid(24, 45);
  Predicates pred;
  PetalSearch petal;
  const AngleBound bound(33);
  std::size_t searches = 0, gathered = 0, moved = 0;
  for (TriangleId t{0}; t < m.triangle_slots(); ++t) {
    EdgeRef shortest = edge_of(t, 0);
    for (unsigned side = 1; side < 3; ++side) {
      const EdgeRef e = edge_of(t, side);
      if (squared_distance(m.point(m.org(e)), m.point(m.dest(e))) <
          squared_distance(m.point(m.org(shortest)), m.point(m.dest(shortest))))
        shortest = e;
    }
    const Point& p = m.point(m.org(shortest));
    const Point& q = m.point(m.dest(shortest));
    const Point& r = m.point(m.apex(shortest));
    const Point x = petal.choose(m, pred, shortest, 33.0, bound.off_center_factor());
    ++searches;
    gathered += petal.gathered_count();
    if (x == off_center(p, q, r, bound.off_center_factor())) continue;
    ++moved;
    CHECK(pred.incircle(p, q, r, x) > 0.0);
    const double a = std::sqrt(squared_distance(q, x)), b = std::sqrt(squared_distance(p, x)),
                 c = std::sqrt(squared_distance(p, q));
    const double at_x = std::acos((a * a + b * b - c * c) / (2 * a * b)) * 180.0 / kPi;
    const double at_p = std::acos((b * b + c * c - a * a) / (2 * b * c)) * 180.0 / kPi;
    CHECK(std::min({at_x, at_p, 180.0 - at_x - at_p}) >= 33.0);
    for (TriangleId u{0}; u < m.triangle_slots(); ++u) {
      const auto [ua, ub, uc] = m.corner_points(u);
      if (pred.incircle(ua, ub, uc, x) > 0.0 && !petal.gathered(u)) CHECK(!"a cavity triangle was not gathered");
    }
    // Its nearest vertex, as the ranking took it from the near corners within reach, is the
    // nearest of all (no subsegment hides one here).
    double nearest = HUGE_VAL;
    for (VertexId v{0}; v < m.vertex_count(); ++v) nearest = std::min(nearest, squared_distance(x, m.point(v)));
    CHECK_EQ(petal.nearest2(x), nearest);
  }
  CHECK(moved > searches / 4);  // the search's own points, not only the fallback, were checked
  CHECK(gathered < 20 * searches);
}

// The search keeps the bound's trigonometry between calls: one search object moving between
// bounds chooses what a fresh one chooses for each.
TEST(petal_search_follows_the_bound_it_is_given) {
  Mesh m = jittered_grid(12, 7);
  Predicates pred;
  PetalSearch kept;
  std::size_t differing = 0;
  for (TriangleId t{0}; t < m.triangle_slots(); ++t)
    for (const double theta : {33.0, 40.0}) {
      const AngleBound bound(theta);
      PetalSearch fresh;
      const Point a = kept.choose(m, pred, edge_of(t, 0), theta, bound.off_center_factor());
      const Point b = fresh.choose(m, pred, edge_of(t, 0), theta, bound.off_center_factor());
      CHECK(a == b);
      if (!(kept.choose(m, pred, edge_of(t, 0), 73.0 - theta, bound.off_center_factor()) == a)) ++differing;
    }
  CHECK(differing > 0);  // the two bounds do choose differently
}
