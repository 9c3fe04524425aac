// The linear certificate of mesh/embedding.h against hand-made meshes whose every fact is known
// from the drawing: sound meshes (fans of slivers, holes, separate pieces) are certified, and
// each mesh that is no triangulation but would pass if one of the certificate's conditions were
// dropped is refused, and found by the pair search (mesh/overlap.h) as well.
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <vector>

#include "harness/check.h"
#include "harness/id_literals.h"
#include "mesh/embedding.h"
#include "mesh/overlap.h"
#include "quality/mesh_builders.h"

using namespace deltri;
using namespace quality_test;

namespace {

// Vertex 0 at `centre` and the rim vertices i = 0..count-1 at angle `step` * i and radius
// radius(i); triangles (0, i, i + 1), and (0, last, first) when `closed`; twins bonded.
template <class Radius>
Mesh fan_around(Point centre, std::uint32_t count, double step, Radius radius, bool closed) {
  Mesh m = mesh_of({centre});
  for (std::uint32_t i = 0; i < count; ++i)
    m.add_vertex({centre.x + radius(i) * std::cos(step * i), centre.y + radius(i) * std::sin(step * i)},
                 VertexKind::Input);
  for (VertexId i{1}; i < count; ++i) m.add_triangle(0_v, i, VertexId{i + 1});
  if (closed) m.add_triangle(0_v, VertexId{count}, 1_v);
  bond_all(m);
  return m;
}

// Appends `piece`'s vertices and triangles to m (its ids shifted), bonding nothing between them.
void add_piece(Mesh& m, const Mesh& piece) {
  const std::uint32_t base = m.vertex_count();
  for (VertexId v{0}; v < piece.vertex_count(); ++v) m.add_vertex(piece.point(v), VertexKind::Input);
  const TriangleId first{m.triangle_slots()};
  for (TriangleId t{0}; t < piece.triangle_slots(); ++t) {
    const auto c = piece.corners(t);
    m.append_triangle(VertexId{base + c[0]}, VertexId{base + c[1]}, VertexId{base + c[2]});
  }
  for (EdgeRef e{0}; e < piece.link.size(); ++e)
    if (piece.link[e] != kNone)
      m.bond(edge_of(TriangleId{first + e.triangle()}, e.side()),
             edge_of(TriangleId{first + piece.link[e].triangle()}, piece.link[e].side()));
}

// A triangle with corners a + (0,0), a + (s,0), a + (0,s).
Mesh small_triangle(Point a, double s) { return mesh_of({a, {a.x + s, a.y}, {a.x, a.y + s}}); }
Mesh with_triangle(Mesh m) {
  m.add_triangle(0_v, 1_v, 2_v);
  return m;
}

// grid(5) without the two triangles of its middle square: an annulus with a 1 x 1 hole at [2, 3]^2.
Mesh annulus() {
  Mesh m = grid(5);
  m.kill_triangle(TriangleId{2 * (2 * 5 + 2)});
  m.kill_triangle(TriangleId{2 * (2 * 5 + 2) + 1});
  return m;
}

bool overlap_found(const Mesh& m) {
  Predicates pred;
  return search_overlap(m, pred).has_value() && find_overlap(m, pred).has_value();
}

bool certified(const Mesh& m) {
  Predicates pred;
  return certify_embedding(m, pred);
}

bool all_counter_clockwise(const Mesh& m, Predicates& pred) {
  for (TriangleId t{0}; t < m.triangle_slots(); ++t) {
    if (!m.is_live(t)) continue;
    const auto [a, b, c] = m.corner_points(t);
    if (pred.orient2d(a, b, c) <= 0) return false;
  }
  return true;
}

// A vertex left by two boundary edges.
bool has_bow_tie(const Mesh& m) {
  std::vector<int> leaving(m.vertex_count());
  for (EdgeRef e{0}; e < m.corner.size(); ++e)
    if (m.is_live(triangle_of(e)) && m.link[e] == kNone && ++leaving[m.org(e)] == 2) return true;
  return false;
}

// Fans sharing their centre 0 at the origin: fan i covers the directions from `from[i]` to
// `to[i]` (radians, counter-clockwise) with `count` triangles on a rim of radius `radius[i]`; no
// twins between fans. Each is a bow tie at 0 as soon as there are two.
Mesh fans_at_origin(const std::vector<double>& from, const std::vector<double>& to, const std::vector<double>& radius,
                    std::uint32_t count) {
  Mesh m = mesh_of({{0, 0}});
  for (std::size_t f = 0; f < from.size(); ++f) {
    const VertexId first{m.vertex_count()};
    for (std::uint32_t i = 0; i <= count; ++i) {
      const double a = from[f] + (to[f] - from[f]) * i / count;
      m.add_vertex({radius[f] * std::cos(a), radius[f] * std::sin(a)}, VertexKind::Input);
    }
    for (std::uint32_t i = 0; i < count; ++i) m.add_triangle(0_v, VertexId{first + i}, VertexId{first + i + 1});
  }
  bond_all(m);
  return m;
}

constexpr double kPi = std::numbers::pi;

}  // namespace

TEST(sound_meshes_are_certified) {
  CHECK(certified(square_fan()));
  CHECK(certified(grid(7)));
  CHECK(certified(annulus()));
  // 20,000 slivers from one vertex of a convex polygon (finding 10's fan), open and closed.
  const auto unit = [](std::uint32_t) { return 1.0; };
  CHECK(certified(fan_around({0, 0}, 20001, 3.0 / 20000, unit, false)));
  CHECK(certified(fan_around({0.5, 0.25}, 20000, 2 * std::numbers::pi / 20000, unit, true)));
}

// A separate triangle in the annulus's hole is sound: the outer loop winds once around it and
// the hole's loop (clockwise) once the other way. Put in the ring it lies over the annulus, with
// a boundary of its own that meets no other: only the loops' winding (W) refuses it.
TEST(a_second_sheet_is_refused_and_a_piece_in_a_hole_is_not) {
  Mesh in_hole = annulus();
  add_piece(in_hole, with_triangle(small_triangle({2.2, 2.2}, 0.5)));
  CHECK(certified(in_hole));
  CHECK(!overlap_found(in_hole));
  Mesh on_ring = annulus();
  add_piece(on_ring, with_triangle(small_triangle({3.2, 2.2}, 0.5)));
  CHECK(!certified(on_ring));
  CHECK(overlap_found(on_ring));
  // A whole sheet over another: a grid over a larger one.
  Mesh sheets = grid(4);
  Mesh upper = grid(2);
  for (Point& p : upper.points) p = {0.5 + 0.7 * p.x, 0.5 + 0.7 * p.y};
  add_piece(sheets, upper);
  CHECK(!certified(sheets));
  CHECK(overlap_found(sheets));
}

// Separate unit squares on a lattice, 2 apart: many loops whose lowest vertices share rows and
// columns, so the rays of the winding test pass exactly through other loops' vertices and along
// their horizontal edges. Sound as they are, and with a triangle left of a row; a triangle over a
// square or on its edge is refused. (With many more loops in a row the ray work exceeds the
// certificate's budget and the pair search decides.)
TEST(many_loops_on_a_lattice) {
  Mesh squares;
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 10; ++j) {
      Mesh square = grid(1);
      for (Point& p : square.points) p = {p.x + 2 * i, p.y + 2 * j};
      add_piece(squares, square);
    }
  CHECK(certified(squares));
  for (const Point corner : {Point{0, 0}, Point{18.5, 0.5}, Point{11, 10.25}, Point{-1, 10}}) {
    Mesh m = squares;
    add_piece(m, with_triangle(small_triangle(corner, 0.5)));
    CHECK_EQ(certified(m), corner.x == -1);
    CHECK_EQ(overlap_found(m), corner.x != -1);
  }
}

// A closed fan wound twice around its centre (rim at radius 1, then 2): every triangle is
// counter-clockwise and every twin sound, but its one boundary loop crosses itself.
TEST(a_fan_wound_twice_is_refused) {
  const Mesh m = fan_around({0, 0}, 24, 2 * std::numbers::pi / 12, [](std::uint32_t i) { return i < 12 ? 1.0 : 2.0; }, true);
  CHECK(!certified(m));
  CHECK(overlap_found(m));
}

// An open fan turning through 1.25 turns, its rim spiralling out or in: it lies over itself.
TEST(a_fan_over_itself_is_refused) {
  for (const double grow : {1.0 / 40, -1.0 / 40}) {
    const Mesh m = fan_around({0, 0}, 41, 2.5 * std::numbers::pi / 40, [&](std::uint32_t i) { return 1.5 + grow * (i - 20.0); }, false);
    CHECK(!certified(m));
    CHECK(overlap_found(m));
  }
}

// The square fan cut open along its spoke to (1, 0), the last triangle ending at (0.5, 0) on that
// spoke instead: a corner on the first triangle's edge, where the two boundary edges at the centre
// follow each other back along one line (they share the centre, so only the turn test sees it).
TEST(a_boundary_doubling_back_is_refused) {
  Mesh m = mesh_of({{0, 0}, {1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}, {0.5, 0}});
  for (std::uint32_t i = 0; i < 7; ++i) m.add_triangle(0_v, VertexId{1 + i}, VertexId{2 + i});
  m.add_triangle(0_v, 8_v, 9_v);
  bond_all(m);
  CHECK(!certified(m));
  Predicates pred;
  const auto found = search_overlap(m, pred);
  CHECK(found.has_value() && !found->interiors_overlap);
}

// Two pieces touching at a vertex: sharing it (a bow tie: certified when sound, refused when the
// second piece turns into the first) or at one place under two ids (a corner on the other piece).
TEST(pieces_touching_at_a_vertex) {
  Mesh bow_tie = square_fan();  // ring vertex 2 is the corner (1, 1)
  const VertexId v = bow_tie.add_vertex({2, 1}, VertexKind::Input);
  bow_tie.add_vertex({1, 2}, VertexKind::Input);
  bow_tie.add_triangle(2_v, v, VertexId{v + 1});
  CHECK(certified(bow_tie));
  CHECK(!overlap_found(bow_tie));
  Mesh overlapping = square_fan();  // the same, turned into the square
  const VertexId w = overlapping.add_vertex({0.5, 0.8}, VertexKind::Input);
  overlapping.add_vertex({0.8, 0.5}, VertexKind::Input);
  overlapping.add_triangle(2_v, w, VertexId{w + 1});
  CHECK(!certified(overlapping));
  CHECK(overlap_found(overlapping));
  Mesh two_ids = square_fan();
  add_piece(two_ids, with_triangle(small_triangle({1, 1}, 0.5)));
  CHECK(!certified(two_ids));
  Predicates pred;
  const auto found = search_overlap(two_ids, pred);
  CHECK(found.has_value() && !found->interiors_overlap);
}

// Fans of slivers touching at their centre, two to four of them round it in separate sectors, a
// bow tie of all the fans, are certified (so is a lone fan): sectors starting or ending on the
// direction +x, where the winding test's ray starts, or on -x; two sectors 0.001 radians apart.
// The pair search agrees on the four fans made of 8,000 slivers.
TEST(fans_touching_at_a_vertex_are_certified) {
  CHECK(certified(fans_at_origin({0}, {1}, {1}, 500)));
  CHECK(certified(fans_at_origin({0, 3}, {1, 4}, {1, 2}, 500)));
  CHECK(certified(fans_at_origin({0.1, 1.6, 3.2, 4.8}, {1.5, 3.1, 4.7, 6.2}, {1, 2, 1, 3}, 200)));
  CHECK(certified(fans_at_origin({-1, 0.5, 2}, {0, 1.999, 3}, {1, 1, 1}, 100)));
  CHECK(certified(fans_at_origin({kPi, 0.2}, {kPi + 1, 3}, {1, 2}, 100)));
  const Mesh m = fans_at_origin({0.1, 1.6, 3.2, 4.8}, {1.5, 3.1, 4.7, 6.2}, {1, 2, 1, 3}, 2000);
  CHECK(!overlap_found(m));
}

// Fans at one centre whose sectors overlap, each refused and found by the pair search: one fan
// starting inside another; one inside another; loops that would cross at the centre (one fan over
// the upper half, one over the left half); two fans meeting along a spoke without twins (an edge
// reaching the centre and one leaving it in one direction); one fan over the ends of two others.
TEST(fans_overlapping_at_a_vertex_are_refused) {
  for (const Mesh& m : {fans_at_origin({0, 0.5}, {1, 1.5}, {1, 2}, 50),  //
                        fans_at_origin({0, 0.25}, {1, 0.75}, {1, 2}, 50),
                        fans_at_origin({0, kPi / 2}, {kPi, 3 * kPi / 2}, {1, 1}, 2),
                        fans_at_origin({0, 1, 3}, {1, 2, 4}, {1, 2, 1}, 10),
                        fans_at_origin({0, 1.5, 0.8}, {1, 2.5, 1.7}, {1, 2, 1}, 10)}) {
    CHECK(!certified(m));
    CHECK(overlap_found(m));
  }
}

// A bow tie of two fans lying over a grid, inside it, touching nothing: its edges at the centre
// alternate and pair as the fans do and meet no other boundary edge, so only the winding test
// sees the second sheet, at the lowest vertex of the right-hand fan, which is the bow tie's
// centre. Over the annulus's hole instead, with the centre on the hole's corner (2, 2) or
// inside the hole, it is sound.
TEST(a_bow_tie_over_a_sheet_is_refused) {
  const auto with_bow_tie = [](Mesh m, Point centre, double size) {
    Mesh tie = fans_at_origin({-0.5, 2}, {0.5, 3}, {size, size}, 3);
    for (Point& p : tie.points) p = {centre.x + p.x, centre.y + p.y};
    add_piece(m, tie);
    return m;
  };
  for (const Point centre : {Point{1.5, 1.5}, Point{3.5, 2.5}, Point{2, 2.5}}) {
    const Mesh m = with_bow_tie(annulus(), centre, 0.4);
    CHECK(!certified(m));
    CHECK(overlap_found(m));
  }
  const Mesh in_hole = with_bow_tie(annulus(), {2.5, 2.5}, 0.4);
  CHECK(certified(in_hole));
  CHECK(!overlap_found(in_hole));
}

// A square with a triangular hole whose corner touches the square's boundary: one boundary loop
// that passes the touching vertex twice. A triangle in the annulus's hole touching the hole's
// corner (2, 2): two loops touching at a vertex. Both sound; moved into the ring, refused.
TEST(loops_touching_themselves_and_each_other) {
  Mesh notch = grid(4);
  notch.kill_triangle(TriangleId{9});  // (1, 1), (1, 2), (0, 2) of the square at (0, 1)
  CHECK(certified(notch));
  CHECK(!overlap_found(notch));
  Mesh touching = annulus();
  const VertexId corner{2 * 6 + 2};
  const VertexId a = touching.add_vertex({2.6, 2.2}, VertexKind::Input);
  touching.add_vertex({2.2, 2.6}, VertexKind::Input);
  touching.add_triangle(corner, a, VertexId{a + 1});
  CHECK(certified(touching));
  CHECK(!overlap_found(touching));
  Mesh into_ring = annulus();
  const VertexId b = into_ring.add_vertex({1.6, 1.8}, VertexKind::Input);
  into_ring.add_vertex({1.8, 1.6}, VertexKind::Input);
  into_ring.add_triangle(corner, b, VertexId{b + 1});
  CHECK(!certified(into_ring));
  CHECK(overlap_found(into_ring));
}

// Random subsets of a grid's triangles: full of bow ties, loops touching themselves and each
// other, all sound; then with one vertex moved at random, or with a triangle added at a random
// vertex (a new bow tie, often over the others), half the time on a lattice of quarter units. With
// every triangle counter-clockwise, certificate and pair search must agree both ways (these
// meshes are far inside the certificate's budget).
TEST(certificate_agrees_with_the_pair_search_on_bow_ties) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> near(-0.8, 0.8), keep(0, 1);
  std::uniform_int_distribution<std::uint32_t> vertex(0, 35);
  const auto moved = [&](Point p, bool lattice) {
    p = {p.x + near(random), p.y + near(random)};
    return lattice ? Point{std::round(4 * p.x) / 4, std::round(4 * p.y) / 4} : p;
  };
  Predicates pred;
  int sound = 0, unsound = 0, tied = 0;
  for (int run = 0; run < 9000; ++run) {
    Mesh m = grid(5);
    const double share = 0.3 + 0.6 * keep(random);
    for (TriangleId t{0}; t < m.triangle_slots(); ++t)
      if (keep(random) > share) m.kill_triangle(t);
    const VertexId v{vertex(random)};
    if (run % 3 == 1) m.points[v] = moved(m.points[v], run % 2);
    if (run % 3 == 2) {
      const VertexId a = m.add_vertex(moved(m.points[v], run % 2), VertexKind::Input);
      const VertexId b = m.add_vertex(moved(m.points[v], run % 2), VertexKind::Input);
      if (pred.orient2d(m.points[v], m.points[a], m.points[b]) > 0) m.add_triangle(v, a, b);
      else m.add_triangle(v, b, a);
    }
    tied += has_bow_tie(m);
    if (!all_counter_clockwise(m, pred) || m.live_triangles() == 0) continue;
    const bool found = search_overlap(m, pred).has_value();
    CHECK_EQ(certify_embedding(m, pred), !found);
    if (run % 3 == 0) CHECK(!found);
    ++(found ? unsound : sound);
  }
  CHECK(sound > 3000);
  CHECK(unsound > 1000);
  CHECK(tied > 6000);
}

// Random meshes: the annulus with one vertex moved a little and a small separate triangle added,
// both at random (half the time on a lattice of quarter units, for exact coincidences and collinear
// corners). When every triangle is counter-clockwise, the certificate and the pair search must
// agree: the annulus has no bow tie, so a sound mesh must be certified, and no mesh with an
// overlap or a T-junction.
TEST(certificate_agrees_with_the_pair_search) {
  std::mt19937 random(42);
  std::uniform_real_distribution<double> anywhere(-0.5, 5.5), near(-0.6, 0.6);
  std::uniform_int_distribution<std::uint32_t> vertex(0, 35);
  const auto moved = [&](Point p, bool lattice) {
    p = {p.x + near(random), p.y + near(random)};
    return lattice ? Point{std::round(4 * p.x) / 4, std::round(4 * p.y) / 4} : p;
  };
  Predicates pred;
  int sound = 0, unsound = 0;
  for (int run = 0; run < 20000; ++run) {
    Mesh m = annulus();
    const VertexId v{vertex(random)};
    m.points[v] = moved(m.points[v], run % 2);
    const Point o = moved({anywhere(random), anywhere(random)}, run % 4 < 2);
    const Point a = moved(o, run % 4 < 2), b = moved(o, run % 4 < 2), c = moved(o, run % 4 < 2);
    add_piece(m, with_triangle(pred.orient2d(a, b, c) > 0 ? mesh_of({a, b, c}) : mesh_of({a, c, b})));
    bool counter_clockwise = true;
    for (TriangleId t{0}; t < m.triangle_slots(); ++t) {
      if (!m.is_live(t)) continue;
      const auto [a, b, c] = m.corner_points(t);
      counter_clockwise = counter_clockwise && pred.orient2d(a, b, c) > 0;
    }
    if (!counter_clockwise) continue;
    const bool found = search_overlap(m, pred).has_value();
    CHECK_EQ(certify_embedding(m, pred), !found);
    ++(found ? unsound : sound);
  }
  CHECK(sound > 1000);
  CHECK(unsound > 1000);
}
