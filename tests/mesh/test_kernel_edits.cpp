// The kernel operations the constrained Delaunay and Delaunay stages edit through (issue 20): the
// one Lawson routine in both layouts, the split layouts, the constrained editor's exact index, the
// subsegment edits, assembly from corner lists and the ghost ring. Checked against facts computed
// independently (exact incircle over every edge, hand-derived triangle sets), not against the code.
#include <cmath>

#include "harness/check.h"
#include "harness/id_literals.h"
#include "mesh/assemble.h"
#include "mesh/constrained_editor.h"
#include "mesh/ghosts.h"
#include "mesh/lawson.h"
#include "mesh/operations.h"
#include "mesh/subsegments.h"
#include "mesh_checks.h"

using namespace deltri;
using namespace meshcheck;

namespace {

// The fan from vertex 0 of n + 2 points on a flat ellipse (a convex polygon, angles jittered so no
// four points are cocircular): its long thin triangles are far from Delaunay.
Mesh bad_fan(std::size_t n) {
  std::vector<Point> pts;
  for (std::size_t k = 0; k < n + 2; ++k) {
    const double a = 2 * 3.141592653589793 * (static_cast<double>(k) + 0.1 * static_cast<double>(k % 3)) /
                     static_cast<double>(n + 2);
    pts.push_back({3 * std::cos(a), std::sin(a)});
  }
  std::vector<Triple> tris;
  for (VertexId i{1}; i <= n; ++i) tris.push_back({0, i, i + 1});
  return make_mesh(pts, tris);
}

template <FlipLayout layout>
Mesh repaired(std::size_t n) {
  Mesh m = bad_fan(n);
  Predicates pred;
  std::vector<EdgeRef> stack;
  for (EdgeRef e{0}; e < m.corner.size(); ++e)
    if (m.link[e] != kNone) stack.push_back(e);
  int flips = 0;
  lawson<layout, LawsonScope::Everywhere>(
      m, stack, kNone,
      [&](EdgeRef e) {
        const EdgeRef f = m.link[e];
        return f != kNone && pred.incircle(m.point(m.org(e)), m.point(m.dest(e)), m.point(m.apex(e)),
                                           m.point(m.apex(f))) > 0;
      },
      [&](EdgeRef, EdgeRef) { ++flips; });
  CHECK(flips > 0);
  return m;
}

}  // namespace

TEST(lawson_everywhere_reaches_the_delaunay_triangulation_in_both_layouts) {
  const Mesh before = bad_fan(12);
  REQUIRE(delaunay_faults(before) > 0);
  const Mesh turn = repaired<FlipLayout::Turn>(12);
  const Mesh keep = repaired<FlipLayout::KeepOrigins>(12);
  CHECK_EQ(all_faults(turn), 0);
  CHECK_EQ(all_faults(keep), 0);
  CHECK_EQ(delaunay_faults(turn), 0);
  CHECK_EQ(delaunay_faults(keep), 0);
  // General position: the Delaunay triangulation is unique, whichever slots hold it.
  CHECK(triangle_set(turn) == triangle_set(keep));
}

TEST(outer_edges_start_and_end_opposite_the_old_apex) {
  // Square 0,1,2,3 split by 0->2; flip 0->2 from the triangle (0, 2, 3): old apex 3.
  for (const bool keep : {false, true}) {
    Mesh m = unit_square();
    const EdgeRef e = find_edge(m, 0, 2), f = m.link[e];
    const VertexId apex = m.apex(e);
    if (keep) flip<FlipLayout::KeepOrigins>(m, e);
    else flip<FlipLayout::Turn>(m, e);
    const auto outer = keep ? outer_edges<FlipLayout::KeepOrigins>(e, f) : outer_edges<FlipLayout::Turn>(e, f);
    CHECK_EQ(m.apex(outer[0]), apex);
    CHECK_EQ(m.apex(outer[3]), apex);
    CHECK(m.apex(outer[1]) != apex);
    CHECK(m.apex(outer[2]) != apex);
    for (const EdgeRef o : outer) CHECK_EQ(m.link[o], kNone);  // the square's sides
  }
}

TEST(split_layouts_hold_the_same_triangles_rotated) {
  Mesh first = make_mesh({{0, 0}, {4, 0}, {0, 4}, {1, 1}}, {{0, 1, 2}});
  Mesh last = first;
  split_triangle<SplitLayout::VertexFirst>(first, 0_e, 3_v);
  split_triangle<SplitLayout::VertexLast>(last, 0_e, 3_v);
  CHECK(triangle_set(first) == triangle_set(last));
  CHECK_EQ(all_faults(last), 0);
  // VertexLast: n1 = (b, c, v), n2 = (c, a, v).
  CHECK_EQ(last.corner[3], 1u);
  CHECK_EQ(last.corner[5], 3u);
  CHECK_EQ(last.corner[6], 2u);
  CHECK_EQ(last.corner[8], 3u);
  CHECK_EQ(first.corner[3], 3u);
}

TEST(constrained_editor_keeps_its_index_exact_and_the_mesh_delaunay) {
  const std::vector<Point> pts = uniform(60, 7);
  Mesh m = mesh_of({{-1, -1}, {3, -1}, {-1, 3}});
  m.add_triangle(0_v, 1_v, 2_v);
  m.enable_subsegments();
  Predicates pred;
  ConstrainedEditor ed(m, pred);
  for (const Point& p : pts) {
    const VertexId v = m.add_vertex(p, VertexKind::Input);
    const Location at = locate(m, pred, p, kNone);
    REQUIRE(at.status == LocateStatus::InTriangle);
    ed.insert_in_triangle(at.edge, v);
  }
  CHECK_EQ(all_faults(m), 0);
  CHECK_EQ(delaunay_faults(m), 0);
  for (VertexId v{0}; v < m.vertex_count(); ++v) {
    const EdgeRef e = ed.leaving(v);
    REQUIRE(e != kNone);
    CHECK_EQ(m.org(e), v);
  }
}

TEST(constrain_and_unconstrain_keep_twins_in_step) {
  Mesh m = unit_square();
  m.enable_subsegments();
  const EdgeRef e = find_edge(m, 0, 2);
  const SubsegmentId id = constrain(m, e, {0_v, 2_v, 5, 0});
  CHECK_EQ(m.subseg[e], id);
  CHECK_EQ(m.subseg[m.link[e]], id);
  const Subsegment old = unconstrain(m, m.link[e]);
  CHECK_EQ(old.marker, 5);
  CHECK_EQ(m.subseg[e], kNone);
  CHECK_EQ(m.subsegments[id].a, kNone);
  drop_dead_subsegments(m);
  CHECK(m.subsegments.empty());
  CHECK_EQ(constrain_boundary(m, 1), 4u);
  CHECK_EQ(constrain_boundary(m, 1), 0u);
}

TEST(peel_boundary_triangle_moves_the_subsegment_onto_its_other_sides) {
  // Square with a vertex 4 just inside the bottom side; the triangle (0, 1, 4) is peeled.
  Mesh m = make_mesh({{0, 0}, {2, 0}, {2, 2}, {0, 2}, {1, 0.1}},
                     {{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}});
  constrain_boundary(m, 3);
  const EdgeRef bottom = find_edge(m, 0, 1);
  const auto [av, vb] = peel_boundary_triangle(m, bottom);
  CHECK_EQ(m.live_triangles(), 3u);
  CHECK_EQ(m.org(av), 0u);
  CHECK_EQ(m.dest(av), 4u);
  CHECK_EQ(m.org(vb), 4u);
  CHECK_EQ(m.dest(vb), 1u);
  CHECK_EQ(m.link[av], kNone);
  CHECK_EQ(m.link[vb], kNone);
  const Subsegment& s1 = m.subsegments[m.subseg[av]];
  const Subsegment& s2 = m.subsegments[m.subseg[vb]];
  CHECK(s1.a == 0u && s1.b == 4u && s1.marker == 3);
  CHECK(s2.a == 4u && s2.b == 1u && s2.marker == 3);
  m.compact_triangles();
  CHECK_EQ(all_faults(m), 0);
}

TEST(assemble_triangles_pairs_edges_and_reports_the_first_defect) {
  Predicates pred;
  Mesh m = mesh_of({{0, 0}, {1, 0}, {1, 1}, {0, 1}, {2, 0}, {0.5, -1}});
  const std::vector<std::uint32_t> good{0, 1, 2, 0, 2, 3, 1, 4, 2};
  CHECK(assemble_triangles(m, pred, good, 3, 3).kind == AssemblyProblem::Kind::None);
  CHECK_EQ(all_faults(m), 0);
  CHECK_EQ(m.link[find_edge(m, 0, 1)], kNone);
  CHECK(m.link[find_edge(m, 0, 2)] != kNone);
  using Kind = AssemblyProblem::Kind;
  const std::vector<std::uint32_t> repeated{0, 1, 2, 3, 3, 2};
  CHECK(assemble_triangles(m, pred, repeated, 2, 3).kind == Kind::RepeatedVertex);
  const std::vector<std::uint32_t> clockwise{0, 2, 1};
  const AssemblyProblem cw = assemble_triangles(m, pred, clockwise, 1, 3);
  CHECK(cw.kind == Kind::Clockwise && cw.first == 0u);
  const std::vector<std::uint32_t> same_way{0, 1, 2, 0, 1, 3};
  const AssemblyProblem o = assemble_triangles(m, pred, same_way, 2, 3);
  CHECK(o.kind == Kind::Overlap && o.first == 0u && o.second == 1u);
  const std::vector<std::uint32_t> three{0, 1, 2, 1, 0, 5, 0, 1, 3};
  CHECK(assemble_triangles(m, pred, three, 3, 3).kind == Kind::SharedEdge);
}

TEST(pair_twins_refuses_edges_that_are_not_opposite) {
  Mesh m = mesh_of({{0, 0}, {1, 0}, {1, 1}, {0, 1}});
  const TriangleId t = append_unlinked(m, 0_v, 1_v, 2_v), u = append_unlinked(m, 0_v, 2_v, 3_v);
  CHECK(!pair_twins(m, edge_of(t, 0), edge_of(u, 0)));  // 0->1 against 0->2
  CHECK(pair_twins(m, edge_of(t, 2), edge_of(u, 0)));   // 2->0 against 0->2
  CHECK(!pair_twins(m, edge_of(t, 2), edge_of(u, 0)));  // already paired
  CHECK_EQ(all_faults(m), 0);
}

TEST(ghost_ring_covers_the_hull_and_goes_away) {
  Mesh m = mesh_of({{0, 0}, {1, 0}, {0, 1}});
  seed_with_ghosts(m, 0_v, 1_v, 2_v);
  CHECK_EQ(m.live_triangles(), 4u);
  for (EdgeRef e{0}; e < m.corner.size(); ++e) CHECK(m.link[e] != kNone);  // a closed surface
  for (EdgeRef e{0}; e < m.corner.size(); ++e) CHECK_EQ(m.link[m.link[e]], e);
  remove_ghosts(m);
  CHECK_EQ(m.triangle_slots(), 1u);
  CHECK(triangle_set(m) == (std::vector<Triple>{{0, 1, 2}}));
  CHECK_EQ(all_faults(m), 0);
}
