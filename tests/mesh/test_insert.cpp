// insert_vertex: interior, on edges, on vertices, outside, and around subsegments.
#include "harness/check.h"
#include "harness/id_literals.h"
#include "mesh/operations.h"
#include "mesh_checks.h"

using namespace deltri;
using namespace meshcheck;

namespace {

// The unit square refined by inserting n random interior points one by one.
Mesh random_square_mesh(std::size_t n, unsigned seed) {
  Mesh m = unit_square();
  Predicates pred;
  EdgeRef hint{0};
  for (const Point& p : uniform(n, seed)) {
    const VertexId v = m.add_vertex(p, VertexKind::Free);
    const InsertResult r = insert_vertex(m, pred, v, hint);
    if (r.status == InsertStatus::Inserted) hint = r.edge;
  }
  return m;
}

}  // namespace

TEST(insert_random_points_keeps_delaunay) {
  Predicates pred;
  Mesh m = unit_square();
  EdgeRef hint{0};
  const auto pts = uniform(600, 21);
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const VertexId v = m.add_vertex(pts[i], VertexKind::Free);
    const InsertResult r = insert_vertex(m, pred, v, hint);
    REQUIRE(r.status == InsertStatus::Inserted);
    CHECK_EQ(m.org(r.edge), v);
    hint = r.edge;
    if (i % 100 == 0) {
      CHECK_EQ(all_faults(m), 0);
      CHECK_EQ(delaunay_faults(m), 0);
    }
  }
  CHECK_EQ(all_faults(m), 0);
  CHECK_EQ(delaunay_faults(m), 0);
  CHECK_EQ(euler_characteristic(m), 1);
  CHECK_EQ(static_cast<std::size_t>(m.live_triangles()), 2 * m.vertex_count() - 2 - 4);
}

TEST(insert_on_interior_and_boundary_edges) {
  Predicates pred;
  Mesh m = unit_square();
  const VertexId c = m.add_vertex({0.5, 0.5}, VertexKind::Free);
  InsertResult r = insert_vertex(m, pred, c, 0_e);
  REQUIRE(r.status == InsertStatus::Inserted);
  CHECK_EQ(m.live_triangles(), 4u);
  const VertexId b = m.add_vertex({0.25, 0}, VertexKind::Free);
  r = insert_vertex(m, pred, b, r.edge);
  REQUIRE(r.status == InsertStatus::Inserted);
  CHECK_EQ(m.live_triangles(), 5u);
  CHECK_EQ(all_faults(m), 0);
  CHECK_EQ(delaunay_faults(m), 0);
  CHECK_EQ(euler_characteristic(m), 1);
  CHECK(find_edge(m, 0, b) != kNone);
  CHECK(find_edge(m, b, 1) != kNone);
}

TEST(insert_on_a_vertex_is_a_duplicate) {
  Predicates pred;
  Mesh m = random_square_mesh(200, 22);
  const auto before = triangle_set(m);
  const auto corner = m.corner;
  for (std::uint32_t old : {0u, 2u, 57u, 150u}) {
    const VertexId v = m.add_vertex(m.point(VertexId{old}), VertexKind::Free);
    const InsertResult r = insert_vertex(m, pred, v, 0_e);
    CHECK(r.status == InsertStatus::Duplicate);
    CHECK_EQ(m.org(r.edge), old);
  }
  CHECK(m.corner == corner);
  CHECK(triangle_set(m) == before);
}

TEST(insert_outside_changes_nothing) {
  Predicates pred;
  Mesh m = random_square_mesh(100, 23);
  const auto corner = m.corner;
  for (const Point& p : std::vector<Point>{{1.5, 0.5}, {-1, -1}, {0.5, 1.0000001}, {2, 0}, {-3, 1}}) {
    const VertexId v = m.add_vertex(p, VertexKind::Free);
    const InsertResult r = insert_vertex(m, pred, v, 0_e);
    CHECK(r.status == InsertStatus::Outside);
    REQUIRE(r.edge != kNone);
    CHECK_EQ(m.link[r.edge], kNone);
    CHECK(pred.orient2d(m.point(m.org(r.edge)), m.point(m.dest(r.edge)), p) < 0);
  }
  CHECK(m.corner == corner);
}

TEST(insertion_never_flips_a_subsegment) {
  Predicates pred;
  for (const bool constrained : {false, true}) {
    Mesh m = unit_square();
    if (constrained) {
      m.enable_subsegments();
      m.subsegments.push_back({0_v, 2_v, 1, 0});
      m.set_subsegment(find_edge(m, 0, 2), 0_s);
    }
    // (0.6, 0.4) sees the diagonal from inside the circle of the other triangle.
    const VertexId v = m.add_vertex({0.6, 0.4}, VertexKind::Free);
    const InsertResult r = insert_vertex(m, pred, v, 0_e, true);
    REQUIRE(r.status == InsertStatus::Inserted);
    CHECK_EQ(all_faults(m), 0);
    CHECK_EQ(delaunay_faults(m), 0);  // ignores constrained edges
    CHECK_EQ(find_edge(m, 0, 2) != kNone, constrained);  // flipped away unless constrained
    CHECK_EQ(find_edge(m, v, 3) != kNone, !constrained);  // ... for v's edge to (0, 1)
    if (constrained) CHECK_EQ(m.subseg[find_edge(m, 0, 2)], 0u);
  }
}

TEST(insert_on_a_subsegment_splits_it_only_when_allowed) {
  Predicates pred;
  Mesh m = unit_square();
  m.enable_subsegments();
  m.subsegments.push_back({0_v, 2_v, 6, 2});
  m.set_subsegment(find_edge(m, 0, 2), 0_s);
  const VertexId v = m.add_vertex({0.25, 0.25}, VertexKind::Segment);
  const auto corner = m.corner;
  InsertResult r = insert_vertex(m, pred, v, 0_e, false);
  CHECK(r.status == InsertStatus::OnSubsegment);
  CHECK_EQ(m.subseg[r.edge], 0u);
  CHECK(m.corner == corner);
  r = insert_vertex(m, pred, v, 0_e, true);
  REQUIRE(r.status == InsertStatus::Inserted);
  CHECK_EQ(m.subsegments.size(), 2u);
  CHECK_EQ(m.subseg[find_edge(m, 0, v)], 0u);
  CHECK_EQ(m.subseg[find_edge(m, v, 2)], 1u);
  CHECK_EQ(all_faults(m), 0);
  CHECK_EQ(delaunay_faults(m), 0);
}

TEST(insert_outside_the_hull_with_ghosts_grows_it) {
  // A triangle with a ghost beyond each edge, as incremental construction keeps it.
  Predicates pred;
  Mesh m = make_mesh({{0, 0}, {1, 0}, {0, 1}}, {{0, 1, 2}, {1, 0, kGhostVertex}, {2, 1, kGhostVertex},
                                               {0, 2, kGhostVertex}});
  const VertexId v = m.add_vertex({1, 1}, VertexKind::Input);
  const InsertResult r = insert_vertex(m, pred, v, 0_e);
  REQUIRE(r.status == InsertStatus::Inserted);
  std::vector<Triple> real;
  int ghosts = 0;
  for (TriangleId t{0}; t < m.triangle_slots(); ++t) {
    if (!m.is_live(t)) continue;
    Triple a{m.corner[edge_of(t, 0)], m.corner[edge_of(t, 1)], m.corner[edge_of(t, 2)]};
    if (std::find(a.begin(), a.end(), kGhostVertex) != a.end()) { ++ghosts; continue; }
    std::rotate(a.begin(), std::min_element(a.begin(), a.end()), a.end());
    real.push_back(a);
  }
  std::sort(real.begin(), real.end());
  CHECK_EQ(ghosts, 4);
  // (0,0),(1,0),(1,1),(0,1) is cocircular: either diagonal is Delaunay; the flip test is strict.
  CHECK(real == (std::vector<Triple>{{0, 1, 2}, {1, 3, 2}}));
}
