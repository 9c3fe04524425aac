// delete_vertex: the triangulation left behind must be the Delaunay triangulation of the other
// vertices, which for random points (general position) is unique: it is compared with the mesh
// built by inserting those vertices alone.
#include <algorithm>

#include "harness/check.h"
#include "harness/id_literals.h"
#include "mesh/delete_vertex.h"
#include "mesh/operations.h"
#include "mesh_checks.h"

using namespace deltri;
using namespace meshcheck;

namespace {

// The unit square with the points inserted in order; `skip` (an index into pts) is left out.
Mesh square_with(const std::vector<Point>& pts, std::size_t skip) {
  Mesh m = unit_square();
  Predicates pred;
  EdgeRef hint{0};
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const VertexId v = m.add_vertex(pts[i], VertexKind::Free);
    if (i == skip) {
      m.kind[v] = VertexKind::Dead;  // keeps the vertex numbering of the full mesh
      continue;
    }
    const InsertResult r = insert_vertex(m, pred, v, hint);
    if (r.status == InsertStatus::Inserted) hint = r.edge;
  }
  return m;
}

EdgeRef leaving(const Mesh& m, VertexId v) {
  for (EdgeRef e{0}; e < m.corner.size(); ++e)
    if (m.corner[e] == v) return e;
  return kNone;
}

}  // namespace

TEST(deleting_a_vertex_gives_the_delaunay_triangulation_of_the_others) {
  const auto pts = uniform(300, 5);
  Predicates pred;
  for (std::size_t victim : {0u, 17u, 150u, 299u}) {
    Mesh m = square_with(pts, pts.size());
    const VertexId v = static_cast<VertexId>(4 + victim);
    std::vector<TriangleId> created;
    REQUIRE(delete_vertex(m, pred, leaving(m, v), created));
    CHECK(m.kind[v] == VertexKind::Dead);
    CHECK(leaving(m, v) == kNone);
    CHECK_EQ(all_faults(m), 0);
    CHECK_EQ(delaunay_faults(m), 0);
    const Mesh expected = square_with(pts, victim);
    CHECK(triangle_set(m) == triangle_set(expected));
    // `created` lists exactly the live triangles that are new around the hole.
    for (TriangleId t : created) CHECK(m.is_live(t));
    CHECK(!created.empty());
  }
}

TEST(deleting_every_vertex_in_turn_keeps_a_valid_delaunay_mesh) {
  const auto pts = uniform(200, 9);
  Predicates pred;
  Mesh m = square_with(pts, pts.size());
  std::vector<TriangleId> created;
  for (VertexId v{4}; v < m.vertex_count(); v = VertexId{v + 3}) {
    created.clear();
    REQUIRE(delete_vertex(m, pred, leaving(m, v), created));
  }
  CHECK_EQ(all_faults(m), 0);
  CHECK_EQ(delaunay_faults(m), 0);
  std::size_t alive = 0;
  for (VertexId v{0}; v < m.vertex_count(); ++v) alive += m.kind[v] != VertexKind::Dead;
  CHECK_EQ(static_cast<std::size_t>(m.live_triangles()), 2 * alive - 2 - 4);
}

TEST(boundary_vertices_and_subsegment_ends_are_not_deleted) {
  Predicates pred;
  Mesh m = unit_square();
  const VertexId c = m.add_vertex({0.5, 0.5}, VertexKind::Free);
  REQUIRE(insert_vertex(m, pred, c, 0_e).status == InsertStatus::Inserted);
  const BigVector<VertexId> before(m.corner.begin(), m.corner.end());
  std::vector<TriangleId> created;
  CHECK(!delete_vertex(m, pred, leaving(m, 0_v), created));  // a corner of the square
  CHECK(m.corner == before);
  // A subsegment from the centre to a corner pins the centre.
  m.enable_subsegments();
  m.subsegments.push_back({c, 0_v, 1, 0});
  EdgeRef e = find_edge(m, c, 0);
  REQUIRE(e != kNone);
  m.set_subsegment(e, 0_s);
  CHECK(!delete_vertex(m, pred, leaving(m, c), created));
  CHECK(m.corner == before);
  CHECK(created.empty());
}

// The centre of a square lies on both diagonals of its link, so every ear's chord passes through
// it; a circumcentre at the midpoint of a right triangle's hypotenuse is the same case. It must
// still be deletable (Chew's step relies on it), leaving two proper triangles.
TEST(a_vertex_on_a_chord_of_its_four_link_vertices_is_deleted) {
  Predicates pred;
  for (const Point centre : {Point{0.5, 0.5}, Point{0.5, 0.25}}) {
    Mesh m = unit_square();
    const VertexId c = m.add_vertex(centre, VertexKind::Free);
    REQUIRE(insert_vertex(m, pred, c, 0_e).status == InsertStatus::Inserted);
    std::vector<TriangleId> created;
    REQUIRE(delete_vertex(m, pred, leaving(m, c), created));
    CHECK_EQ(all_faults(m), 0);
    CHECK_EQ(delaunay_faults(m), 0);
    CHECK_EQ(static_cast<std::size_t>(m.live_triangles()), std::size_t{2});
    for (TriangleId t : created)
      if (m.is_live(t)) {
        const auto p = m.corner_points(t);
        CHECK(pred.orient2d(p.a, p.b, p.c) > 0);
      }
  }
}
