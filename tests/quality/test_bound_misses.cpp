// The quality account of a final mesh (quality/bound_misses.h) on meshes drawn by hand: which
// triangles miss the bounds, and the cause each is given, known from the drawing.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <numbers>

#include "harness/check.h"
#include "harness/id_literals.h"
#include "quality/bound_misses.h"
#include "quality/mesh_builders.h"

using namespace deltri;
using namespace quality_test;

namespace {

// One triangle o, a, b (counter-clockwise) with o = (0, 0), a = (10, 0), b = (10, 1): its angle at o
// is atan(1/10) = 5.71 degrees. With `segments`, o-a and o-b are subsegments of input segments 0
// and 1 (so o is where two segments meet at 5.71 degrees).
Mesh wedge(bool segments, VertexKind apex) {
  Mesh m = mesh_of({{0, 0}, {10, 0}, {10, 1}});
  m.kind[0] = apex;
  m.add_triangle(0_v, 1_v, 2_v);
  if (segments) {
    m.enable_subsegments();
    m.subsegments.push_back({0_v, 1_v, 1, 0});
    m.subsegments.push_back({2_v, 0_v, 1, 1});
    m.set_subsegment(0_e, 0_s);  // edge 0: o -> a
    m.set_subsegment(2_e, 1_s);  // edge 2: b -> o
  }
  return m;
}

BoundRequest angle(double degrees) {
  BoundRequest r;
  r.angle = AngleBound(degrees);
  return r;
}

}  // namespace

TEST(a_skinny_triangle_between_two_input_segments_is_forced_by_the_input) {
  const BoundMisses b = count_bound_misses(wedge(true, VertexKind::Input), angle(30));
  CHECK_EQ(b.total, 1u);
  CHECK_EQ(b.below_angle, 1u);
  CHECK_EQ(b.small_input_angle, 1u);
  CHECK_EQ(b.not_forced_by_input(), 0u);
  // 5.71 degrees meets a 5 degree bound.
  CHECK_EQ(count_bound_misses(wedge(true, VertexKind::Input), angle(5)).total, 0u);
}

// The input explains a small angle, not a size: the same wedge above an area bound is not forced
// by the input, whether or not it also misses the angle (its area is 5).
TEST(a_triangle_too_large_is_not_forced_by_a_small_input_angle) {
  BoundRequest r = angle(30);
  r.size.max_area = 4;
  const BoundMisses b = count_bound_misses(wedge(true, VertexKind::Input), r);
  CHECK_EQ(b.total, 1u);
  CHECK_EQ(b.below_angle, 1u);
  CHECK_EQ(b.above_size, 1u);
  CHECK_EQ(b.small_input_angle, 0u);
  CHECK_EQ(b.not_forced_by_input(), 1u);
  r.size.max_area = 6;
  CHECK_EQ(count_bound_misses(wedge(true, VertexKind::Input), r).small_input_angle, 1u);
}

// Input segments a (j = (0, 0) to (10, 0), through p = (5, 0)) and b (j to (10, 1)) meet at j at
// 5.71 degrees. The triangle j, r, p with r = (2.5, -30) lies outside that angle, below a: its
// shortest edge j-p runs along a to the junction itself and spans no wedge, so nothing in the input
// explains its 9.5 degrees at r (meshcheck agrees). It was counted as forced by the input: found on
// earcut's touching-holes6.poly at -pq30Y, by comparing the account with meshcheck's.
TEST(an_edge_along_a_segment_to_the_junction_spans_no_wedge) {
  Mesh m = mesh_of({{0, 0}, {5, 0}, {10, 0}, {10, 1}, {2.5, -30}});
  m.kind[1] = VertexKind::Segment;
  m.add_triangle(0_v, 4_v, 1_v);  // below a: 9.5 degrees at r, shortest edge j-p
  m.add_triangle(0_v, 1_v, 3_v);  // inside the angle: 5.71 degrees at j (rule 1)
  m.add_triangle(1_v, 2_v, 3_v);  // inside the angle: shortest edge (10,0)-(10,1) spans it (rule 2)
  bond_all(m);
  m.enable_subsegments();
  m.subsegments.push_back({0_v, 1_v, 1, 0});
  m.subsegments.push_back({1_v, 2_v, 1, 0});
  m.subsegments.push_back({3_v, 0_v, 1, 1});
  m.set_subsegment(3_e, 0_s);  // j -> p
  m.set_subsegment(6_e, 1_s);  // p -> (10, 0)
  m.set_subsegment(5_e, 2_s);  // (10, 1) -> j
  const BoundMisses b = count_bound_misses(m, angle(30));
  CHECK_EQ(b.below_angle, 3u);
  CHECK_EQ(b.small_input_angle, 2u);
  CHECK_EQ(b.other, 1u);
}

// Where two input segments cross, deltri makes the vertex (a Segment vertex on two segments), but
// the angle they cross at is the input's: every mesh keeping the segments has it.
TEST(the_same_angle_at_a_crossing_deltri_made_is_the_inputs) {
  const BoundMisses b = count_bound_misses(wedge(true, VertexKind::Segment), angle(30));
  CHECK_EQ(b.small_input_angle, 1u);
  CHECK_EQ(b.at_input_crossings, 1u);
  CHECK_EQ(b.repaired_input, 0u);
  CHECK_EQ(b.not_forced_by_input(), 0u);
  CHECK_EQ(count_bound_misses(wedge(true, VertexKind::Input), angle(30)).at_input_crossings, 0u);
  // Beyond 60 degrees an angle explains nothing: the 5.71 degree triangle is not inside a small sector
  // when the segments at o meet at 90 degrees (o-a and o-(0,10)).
  Mesh m = mesh_of({{0, 0}, {10, 0}, {10, 1}, {0, 10}});
  m.add_triangle(0_v, 1_v, 2_v);
  m.add_triangle(0_v, 2_v, 3_v);
  m.enable_subsegments();
  m.subsegments.push_back({0_v, 1_v, 1, 0});
  m.subsegments.push_back({3_v, 0_v, 1, 1});
  m.set_subsegment(0_e, 0_s);  // o -> a
  m.set_subsegment(5_e, 1_s);  // (0,10) -> o
  const BoundMisses wide = count_bound_misses(m, angle(30));
  CHECK_EQ(wide.total, 1u);
  CHECK_EQ(wide.other, 1u);
  // The same at a crossing deltri made: a repair's neighbour the crossing's angles do not explain.
  m.kind[0] = VertexKind::Segment;
  const BoundMisses crossing = count_bound_misses(m, angle(30));
  CHECK_EQ(crossing.repaired_input, 1u);
  CHECK_EQ(crossing.at_input_crossings, 0u);
  CHECK_EQ(crossing.not_forced_by_input(), 1u);
}

namespace {

// The thin domain o, a = (10, 0), b = (10, 1) after -c refinement: the hull edge o-a, split at
// s = (5, 0) and t = (8, 0), and the hull edge a-b are pieces of no input segment; with
// `segment`, input segment 0 runs o-p-b, p = (5, 0.5) being a split point of it.
Mesh thin_domain(bool segment) {
  Mesh m = mesh_of({{0, 0}, {5, 0}, {8, 0}, {10, 0}, {5, 0.5}, {10, 1}});
  m.kind[1] = m.kind[2] = m.kind[4] = VertexKind::Segment;
  m.add_triangle(0_v, 1_v, 4_v);  // 5.71 degrees at o
  m.add_triangle(1_v, 2_v, 4_v);  // 9.46 degrees at t; shortest edge s-p
  m.add_triangle(2_v, 3_v, 5_v);  // 26.6 degrees at t; shortest edge a-b
  m.add_triangle(2_v, 5_v, 4_v);  // 15.2 degrees at p; shortest edge t-b
  m.enable_subsegments();
  const auto piece = [&](EdgeRef e, VertexId a, VertexId b, std::uint32_t seg) {
    m.subsegments.push_back({a, b, 1, seg});
    m.set_subsegment(e, SubsegmentId{static_cast<std::uint32_t>(m.subsegments.size() - 1)});
  };
  piece(0_e, 0_v, 1_v, kNone);  // o -> s
  piece(3_e, 1_v, 2_v, kNone);  // s -> t
  piece(6_e, 2_v, 3_v, kNone);  // t -> a
  piece(7_e, 3_v, 5_v, kNone);  // a -> b
  if (segment) {
    piece(10_e, 5_v, 4_v, 0);  // b -> p
    piece(2_e, 4_v, 0_v, 0);   // p -> o
  }
  return m;
}

}  // namespace

// A hull edge meets an input segment at a junction as a segment does: o's 5.71 degrees between the
// hull edge o-a and segment 0 explains the corner at o (rule 1) and the two triangles whose shortest
// edge joins the two inside the corner triangle it cuts off at o (rule 2), as meshcheck's
// convex-hull mode does. When hull pieces counted as no segment at all, those three were "other",
// and -pq20Dc --strict refused dengwirda__mesh2d's lake.poly. The triangle s, t, p lies beyond its
// shortest edge's corner triangle o, s, p, and its circumcentre (6.5, 0.25) in no diametral disk of
// a subsegment at o: nothing forces its 9.46 degrees (rule 2 once explained any edge across a wedge).
TEST(a_hull_edge_meets_an_input_segment_at_a_junction) {
  const BoundMisses b = count_bound_misses(thin_domain(true), angle(30));
  CHECK_EQ(b.below_angle, 4u);
  CHECK_EQ(b.small_input_angle, 3u);
  CHECK_EQ(b.other, 1u);
  CHECK_EQ(b.not_forced_by_input(), 1u);
}

namespace {

// Input segments A (j = (0, 0) along the x axis through a = (1, 0)) and B (j through b, at `degrees`
// from A, |jb| = 1), a and b split points at equal distances from j (a shell), the corner triangle
// j, a, b, and the triangle a, c, b across its edge a-b with c on the bisector of the angle at j, at
// distance `from_j` from j.
Mesh shell_pair(double degrees, double from_j) {
  const double phi = degrees * std::numbers::pi / 180.0;
  const double half = phi / 2.0;
  Mesh m = mesh_of({{0, 0}, {1, 0}, {std::cos(phi), std::sin(phi)}, {from_j * std::cos(half), from_j * std::sin(half)}});
  m.kind[1] = m.kind[2] = VertexKind::Segment;
  m.kind[3] = VertexKind::Free;
  m.add_triangle(0_v, 1_v, 2_v);  // the corner triangle
  m.add_triangle(1_v, 3_v, 2_v);  // across a-b
  bond_all(m);
  m.enable_subsegments();
  m.subsegments.push_back({0_v, 1_v, 1, 0});
  m.subsegments.push_back({2_v, 0_v, 1, 1});
  m.set_subsegment(0_e, 0_s);  // j -> a
  m.set_subsegment(2_e, 1_s);  // b -> j
  return m;
}

// The smallest angle of triangle t of m, in degrees.
double smallest_angle(const Mesh& m, TriangleId t) {
  const auto [a, b, c] = m.corner_points(t);
  const auto at = [](const Point& o, const Point& p, const Point& q) {
    return std::atan2(std::fabs((p.x - o.x) * (q.y - o.y) - (p.y - o.y) * (q.x - o.x)),
                      (p.x - o.x) * (q.x - o.x) + (p.y - o.y) * (q.y - o.y)) * 180.0 / std::numbers::pi;
  };
  return std::min({at(a, b, c), at(b, c, a), at(c, a, b)});
}

}  // namespace

// jburkardt's mesh08.poly at -pq30a0.00004 kept 8 triangles like a, c, b beside 42.3-degree
// junctions (28.58 degrees), and guitar.poly three beside 45-degree ones, where Triangle 1.6 meets
// 30: the edge a-b spans the wedge and joins points at equal distances from j, but c lies beyond
// it, outside the corner triangle, and the circumcentre of a, c, b, 1.63 from j on the bisector,
// lies in neither subsegment's diametral disk. A 45-degree angle does not force that triangle;
// it was counted as forced and not warned of.
TEST(a_triangle_beyond_the_corner_a_shell_cuts_off_is_not_forced) {
  const Mesh m = shell_pair(45, 2.4265);
  CHECK(std::fabs(smallest_angle(m, 1_t) - 28.58) < 0.01);
  const BoundMisses b = count_bound_misses(m, angle(30));
  CHECK_EQ(b.below_angle, 1u);  // the corner triangle has 45, 67.5 and 67.5 degrees
  CHECK_EQ(b.small_input_angle, 0u);
  CHECK_EQ(b.other, 1u);
}

// Below the angle bound the Terminator spares every triangle on an equal-shell edge, not only the
// corner triangle (sparing only the corner cut the shells down without end; Terminator::shell_exempt),
// so such a triangle is forced by the input angle there: a, c, b beyond a 20-degree corner with c 3
// from j, 9.85 degrees (above Theorem 12's floor of 7.05), its circumcentre in no diametral disk at
// j. At -q15 the 20-degree junction is at or above the bound, and the same triangle is not forced.
TEST(below_the_bound_a_triangle_on_a_shell_edge_is_forced) {
  const Mesh m = shell_pair(20, 3.0);
  CHECK(std::fabs(smallest_angle(m, 1_t) - 9.85) < 0.01);
  BoundMisses b = count_bound_misses(m, angle(30));
  CHECK_EQ(b.below_angle, 2u);  // also the corner triangle, 20 degrees at j (rule 1)
  CHECK_EQ(b.small_input_angle, 2u);
  b = count_bound_misses(m, angle(15));
  CHECK_EQ(b.below_angle, 1u);
  CHECK_EQ(b.small_input_angle, 0u);
  CHECK_EQ(b.other, 1u);
}

// A flat triangle just beyond the edge a-b of a 20-degree corner: its circumcentre lies on the
// bisector inside the corner, in the diametral disk of j-a, where the Terminator may leave it
// (Theorem 12). With c 0.05 beyond a-b its smallest angle, 16.1 degrees, is above Theorem 12's floor
// for 20 degrees, arcsin(sin 10 / sqrt 2) = 7.05: forced. With c 0.01 beyond, 3.3 degrees is
// below the floor: no Terminator leaves it, and it is not forced.
TEST(the_diametral_disks_at_a_small_angle_explain_down_to_theorem_12s_floor) {
  const double middle = std::cos(10.0 * std::numbers::pi / 180.0);  // j to the midpoint of a-b
  const Mesh above = shell_pair(20, middle + 0.05);
  CHECK(std::fabs(smallest_angle(above, 1_t) - 16.07) < 0.01);
  BoundMisses b = count_bound_misses(above, angle(30));
  CHECK_EQ(b.below_angle, 2u);  // also the corner triangle, 20 degrees at j (rule 1)
  CHECK_EQ(b.small_input_angle, 2u);
  const Mesh below = shell_pair(20, middle + 0.01);
  CHECK(smallest_angle(below, 1_t) < 7.0);
  b = count_bound_misses(below, angle(30));
  CHECK_EQ(b.below_angle, 2u);
  CHECK_EQ(b.small_input_angle, 1u);
  CHECK_EQ(b.other, 1u);
}

// The pieces of one hull edge, joined at the points refinement put on it, are one edge: s and t are
// not junctions, so the triangles at them are not "next to a repaired crossing", and with no input
// segment nothing but a small hull corner could explain them (o has one hull edge only here).
TEST(the_pieces_of_a_hull_edge_are_one_edge) {
  const BoundMisses b = count_bound_misses(thin_domain(false), angle(30));
  CHECK_EQ(b.below_angle, 4u);
  CHECK_EQ(b.repaired_input, 0u);
  CHECK_EQ(b.other, 4u);
}

TEST(without_segments_a_skinny_triangle_is_unexplained_or_at_the_limits) {
  CHECK_EQ(count_bound_misses(wedge(false, VertexKind::Input), angle(30)).other, 1u);
  BoundRequest r = angle(30);
  r.steiner_limited = true;
  CHECK_EQ(count_bound_misses(wedge(false, VertexKind::Input), r).steiner_limits, 1u);
  r.steiner_limited = false;
  r.segments_kept_whole = true;  // -Y, but the triangle touches no segment
  CHECK_EQ(count_bound_misses(wedge(false, VertexKind::Input), r).other, 1u);
}

TEST(a_triangle_a_few_ulps_across_is_at_the_limit_of_double_precision) {
  const double x = 1e6, ulp = std::nextafter(x, 2 * x) - x;
  Mesh m = mesh_of({{x, 0}, {x + 3 * ulp, 0}, {x, 1}});
  m.add_triangle(0_v, 1_v, 2_v);
  const BoundMisses b = count_bound_misses(m, angle(20));
  CHECK_EQ(b.total, 1u);
  CHECK_EQ(b.double_precision, 1u);
}

TEST(size_bounds_count_separately_and_good_triangles_not_at_all) {
  Mesh m = mesh_of({{0, 0}, {1, 0}, {0.5, std::sqrt(3.0) / 2}});  // equilateral, area 0.433
  m.add_triangle(0_v, 1_v, 2_v);
  CHECK_EQ(count_bound_misses(m, angle(59.9)).total, 0u);
  BoundRequest r = angle(30);
  r.size.max_area = 0.4;
  BoundMisses b = count_bound_misses(m, r);
  CHECK_EQ(b.above_size, 1u);
  CHECK_EQ(b.below_angle, 0u);
  CHECK_EQ(b.other, 1u);
  r.size.max_area = 0.5;
  r.size.max_edge_length = 0.99;
  CHECK_EQ(count_bound_misses(m, r).above_size, 1u);
  r.size.max_edge_length = 1.01;
  CHECK_EQ(count_bound_misses(m, r).total, 0u);
}

// The angle test decides most triangles without atan2 (by tan(bound) against cross / dot) and
// near ties with it: either way a triangle misses exactly when its smallest angle, computed in
// long double here, is below the bound less the relative margin of 1e-12. Bounds 1e-11 and 1e-6
// (relative) either side of the angle take both paths, at scales whose products stay normal. A
// triangle that clears the bound by far is decided by one measure of its smallest angle, whose
// products of squared lengths are subnormal at 1e-80 and 3e-81 (a few bits left): there the corner
// tests must decide.
TEST(the_angle_test_agrees_with_a_long_double_reference_at_and_away_from_ties) {
  int checked = 0;
  for (double scale : {1.0, 1e-150, 1e150, 1e-80, 3e-81})
    for (int n = 1; n <= 12; ++n)
      for (int k = 1; k <= 12; ++k) {
        // (0,0), (n,0), (n,k) scaled: right angle at (n,0); the smallest angle is at the origin
        // when k < n, else at (n,k).
        Mesh m = mesh_of({{0, 0}, {n * scale, 0}, {n * scale, k * scale}});
        m.add_triangle(0_v, 1_v, 2_v);
        const long double at_o = std::atan2((long double)k, (long double)n) * 180.0L / 3.14159265358979323846264338327950288L;
        const long double smallest = std::min(at_o, 90.0L - at_o);
        for (double rel : {-1e-6, -1e-11, 0.0, 1e-11, 1e-6}) {
          const double bound = static_cast<double>(smallest * (1.0L + rel));
          const bool expected = smallest < (long double)bound * (1.0L - 1e-12L);
          CHECK_EQ(count_bound_misses(m, angle(bound)).below_angle, expected ? 1u : 0u);
          ++checked;
        }
      }
  CHECK_EQ(checked, 5 * 12 * 12 * 5);
  // An obtuse triangle (120 degrees at the apex, 30 at the others) against 29.9 and 30.1.
  Mesh obtuse = mesh_of({{0, 0}, {std::sqrt(3.0), 0}, {std::sqrt(3.0) / 2, 0.5}});
  obtuse.add_triangle(0_v, 1_v, 2_v);
  CHECK_EQ(count_bound_misses(obtuse, angle(29.9)).below_angle, 0u);
  CHECK_EQ(count_bound_misses(obtuse, angle(30.1)).below_angle, 1u);
}

// The first pass takes two threads from 100,000 slots: its counts must be those of one pass, on a
// mesh whose misses of every kind lie in both halves. 120,000 separate triangles, each one of
// eight shapes picked by a hash of its number: good (three of the eight), skinny (5.71 degrees),
// too large, both, a slot left dead, and skinny at the limit of double precision. The expected
// counts come from the shapes' own measures here (long double angles and areas), not from the code
// under test.
TEST(the_first_pass_in_two_halves_counts_what_one_pass_counts) {
  constexpr std::uint32_t kTriangles = 120000;
  constexpr double kMaxArea = 1.0;
  Mesh m;
  std::uint64_t below = 0, above = 0, total = 0, precision = 0;
  for (std::uint32_t i = 0; i < kTriangles; ++i) {
    const unsigned shape = (i * 2654435761u) >> 29;  // 0..7
    const double x = 10.0 * (i % 1000) + (shape == 7 ? 1e6 : 0.0), y = 10.0 * (i / 1000);
    const double ulp = std::nextafter(x, 2 * x + 1) - x;
    std::vector<Point> p;
    switch (shape) {
      case 3: p = {{x, y}, {x + 1, y}, {x + 1, y + 0.1}}; break;      // skinny, small
      case 4: p = {{x, y}, {x + 2, y}, {x + 1, y + std::sqrt(3.0)}}; break;  // equilateral, area 1.73
      case 5: p = {{x, y}, {x + 10, y}, {x + 10, y + 1}}; break;      // skinny, area 5
      case 7: p = {{x, y}, {x + 3 * ulp, y}, {x, y + 1}}; break;      // a few ulps across
      default: p = {{x, y}, {x + 1, y}, {x + 0.5, y + std::sqrt(3.0) / 2}};  // equilateral, area 0.43
    }
    const VertexId a{m.vertex_count()};
    for (const Point& q : p) m.add_vertex(q, VertexKind::Input);
    const TriangleId t = m.append_triangle(a, VertexId{a + 1}, VertexId{a + 2});  // no dead slot reused
    if (shape == 6) {
      m.kill_triangle(t);
      continue;
    }
    long double smallest = 180, area = 0;
    for (int k = 0; k < 3; ++k) {
      const Point &o = p[k], &u = p[(k + 1) % 3], &v = p[(k + 2) % 3];
      const long double ux = (long double)u.x - o.x, uy = (long double)u.y - o.y;
      const long double vx = (long double)v.x - o.x, vy = (long double)v.y - o.y;
      const long double cross = ux * vy - uy * vx;
      area = std::fabs(cross) / 2;
      smallest = std::min(smallest, std::atan2(std::fabs(cross), ux * vx + uy * vy) * 180 / 3.14159265358979323846264338327950288L);
    }
    const bool skinny = smallest < 30, large = area > kMaxArea;
    below += skinny;
    above += large;
    total += skinny || large;
    precision += shape == 7;
  }
  CHECK(below > 20000 && above > 20000 && precision > 10000);  // every kind, in quantity
  for (unsigned threads : {1u, 2u, 3u}) {
    BoundRequest r = angle(30);
    r.size.max_area = kMaxArea;
    r.threads = threads;
    const BoundMisses b = count_bound_misses(m, r);
    CHECK_EQ(b.below_angle, below);
    CHECK_EQ(b.above_size, above);
    CHECK_EQ(b.total, total);
    CHECK_EQ(b.double_precision, precision);
    CHECK_EQ(b.other, total - precision);
  }
}

namespace {

// A subsegment of input segment `segment` from a to b on edge `edge` (a -> b) of the mesh.
struct OnEdge {
  EdgeRef edge;
  VertexId a, b;
  std::uint32_t segment;
};

void put_subsegments(Mesh& m, std::initializer_list<OnEdge> list) {
  m.enable_subsegments();
  for (const OnEdge& s : list) {
    m.set_subsegment(s.edge, SubsegmentId{static_cast<std::uint32_t>(m.subsegments.size())});
    m.subsegments.push_back({s.a, s.b, 1, s.segment});
  }
}

// --max-angle=degrees alone (no -q).
BoundRequest max_angle(double degrees) {
  BoundRequest r;
  r.max_angle = LargestAngleBound(degrees);
  return r;
}

// One triangle o = (0, 0), a = (2, 0), b = (-1, 2): its angle at o is 180 - atan(2) = 116.57
// degrees (the dot product (2, 0).(-1, 2) = -2 < 0), at a 33.69 and at b 29.74. `segments` of its
// sides o-a (edge 0) and b-o (edge 2) are subsegments of input segments 0 and 1.
Mesh open_corner(int segments, VertexKind apex) {
  Mesh m = mesh_of({{0, 0}, {2, 0}, {-1, 2}});
  m.kind[0] = apex;
  m.add_triangle(0_v, 1_v, 2_v);
  if (segments == 2) put_subsegments(m, {{0_e, 0_v, 1_v, 0}, {2_e, 2_v, 0_v, 1}});  // o -> a, b -> o
  else put_subsegments(m, {{0_e, 0_v, 1_v, 0}});
  return m;
}

}  // namespace

// An angle above --max-angle between two input segments meeting at a larger angle still: no point
// can remove it, so it is forced by the input (large_input_angle), also under a -q bound the
// triangle meets; a bound above the angle (120) finds nothing.
TEST(an_angle_above_the_bound_between_two_input_segments_is_forced_by_the_input) {
  for (double bound : {90.0, 100.0, 116.0}) {
    const BoundMisses b = count_bound_misses(open_corner(2, VertexKind::Input), max_angle(bound));
    CHECK_EQ(b.total, 1u);
    CHECK_EQ(b.above_max_angle, 1u);
    CHECK_EQ(b.large_input_angle, 1u);
    CHECK_EQ(b.not_forced_by_input(), 0u);
  }
  BoundRequest r = max_angle(90);
  r.angle = AngleBound(20);
  const BoundMisses both = count_bound_misses(open_corner(2, VertexKind::Input), r);
  CHECK_EQ(both.below_angle, 0u);
  CHECK_EQ(both.large_input_angle, 1u);
  CHECK_EQ(count_bound_misses(open_corner(2, VertexKind::Input), max_angle(120)).total, 0u);
  // The same between two segments crossing at a vertex deltri made: the input's angle all the same.
  const BoundMisses crossing = count_bound_misses(open_corner(2, VertexKind::Segment), max_angle(90));
  CHECK_EQ(crossing.large_input_angle, 1u);
  CHECK_EQ(crossing.at_input_crossings, 1u);
  CHECK_EQ(crossing.not_forced_by_input(), 0u);
}

// The same angle with only one side on a segment is not the input's: a point splits it (other).
TEST(an_angle_above_the_bound_not_between_two_input_segments_is_not_forced) {
  const BoundMisses one = count_bound_misses(open_corner(1, VertexKind::Input), max_angle(90));
  CHECK_EQ(one.above_max_angle, 1u);
  CHECK_EQ(one.large_input_angle, 0u);
  CHECK_EQ(one.other, 1u);
  CHECK_EQ(one.not_forced_by_input(), 1u);
}

// Part of a large input angle is not the angle: the 116.57 degrees at o between segments o-a and
// o-b split by a free edge o-c, c at sqrt 5 from o and 100 degrees from a. The triangle o, a, c has
// 100 degrees at o between a segment and a free edge (a point on its bisector could split it), so
// at --max-angle=90 it is not forced; o, c, b (16.57 degrees at o, isosceles) meets the bound.
TEST(an_angle_above_the_bound_inside_a_larger_input_angle_is_not_forced) {
  const double at_c = 100.0 * std::numbers::pi / 180.0;
  Mesh m = mesh_of({{0, 0}, {2, 0}, {-1, 2}, {std::sqrt(5.0) * std::cos(at_c), std::sqrt(5.0) * std::sin(at_c)}});
  m.kind[3] = VertexKind::Free;
  m.add_triangle(0_v, 1_v, 3_v);  // o, a, c
  m.add_triangle(0_v, 3_v, 2_v);  // o, c, b
  bond_all(m);
  put_subsegments(m, {{0_e, 0_v, 1_v, 0}, {5_e, 2_v, 0_v, 1}});  // o -> a, b -> o
  const BoundMisses b = count_bound_misses(m, max_angle(90));
  CHECK_EQ(b.total, 1u);
  CHECK_EQ(b.above_max_angle, 1u);
  CHECK_EQ(b.large_input_angle, 0u);
  CHECK_EQ(b.other, 1u);
  CHECK_EQ(count_bound_misses(m, max_angle(101)).total, 0u);
}

// Next to a small input angle an angle above --max-angle is forced by the rules that force a small
// one there (docs/refinement.md, "Largest-angle bound"). Segments A (o = (0, 0) along the x axis,
// split at r = (3, 0), p = (5, 0) and s = (9, 0)) and B (o towards (10, 1), split at q = (5.1, 0.51))
// meet at o at 5.71 degrees. r, p, q has 101.1 degrees at p ((-2, 0).(0.1, 0.51) = -0.2 < 0), its
// shortest edge p-q joins A and B and r lies in the corner triangle o, p, q that edge cuts off
// (rule 2; its smallest angle, 13.7, above Theorem 12's floor of 2.02 for 5.71): forced. p, s, q
// has 93.6 degrees at q ((-0.1, -0.51).(3.9, -0.51) = -0.13 < 0) with the same shortest edge, but
// s lies beyond the corner triangle and its circumcentre ((7, -0.13), below A) in no diametral
// disk of a subsegment at o: nothing in the input forces it. o, r, q (166 degrees at r) has a
// corner at o and the others in the sector (rule 1): forced.
TEST(an_angle_above_the_bound_beside_a_small_input_angle_is_forced_only_inside_the_corner) {
  Mesh m = mesh_of({{0, 0}, {3, 0}, {5, 0}, {5.1, 0.51}, {9, 0}});
  m.kind[1] = m.kind[2] = m.kind[3] = m.kind[4] = VertexKind::Segment;
  m.add_triangle(0_v, 1_v, 3_v);  // o, r, q: edges 0 o->r, 1 r->q, 2 q->o
  m.add_triangle(1_v, 2_v, 3_v);  // r, p, q: edges 3 r->p, 4 p->q, 5 q->r
  m.add_triangle(2_v, 4_v, 3_v);  // p, s, q: edges 6 p->s, 7 s->q, 8 q->p
  bond_all(m);
  // o -> r, r -> p, p -> s on A; q -> o on B
  put_subsegments(m, {{0_e, 0_v, 1_v, 0}, {3_e, 1_v, 2_v, 0}, {6_e, 2_v, 4_v, 0}, {2_e, 3_v, 0_v, 1}});
  const BoundMisses b = count_bound_misses(m, max_angle(90));
  CHECK_EQ(b.above_max_angle, 3u);
  CHECK_EQ(b.small_input_angle, 2u);
  CHECK_EQ(b.large_input_angle, 0u);
  CHECK_EQ(b.other, 1u);
  CHECK_EQ(b.not_forced_by_input(), 1u);
}
