// locate against brute force, on Delaunay meshes, non-Delaunay meshes and a non-convex mesh.
#include "delaunay/incremental.h"
#include "harness/check.h"
#include "harness/id_literals.h"
#include "mesh/operations.h"
#include "mesh_checks.h"

using namespace deltri;
using namespace meshcheck;

namespace {

// Whether `loc` is a true answer for p, judged with exact predicates over the whole mesh.
bool correct(const Mesh& m, const Point& p, const Location& loc) {
  Predicates pred;
  auto side = [&](EdgeRef e) { return pred.orient2d(m.point(m.org(e)), m.point(m.dest(e)), p); };
  if (loc.status == LocateStatus::Outside) {
    for (TriangleId t{0}; t < m.triangle_slots(); ++t)
      if (m.is_live(t) && side(edge_of(t, 0)) >= 0 && side(edge_of(t, 1)) >= 0 && side(edge_of(t, 2)) >= 0) return false;
    return loc.edge != kNone && m.link[loc.edge] == kNone && side(loc.edge) < 0;
  }
  if (loc.edge == kNone || !m.is_live(triangle_of(loc.edge))) return false;
  const EdgeRef e = loc.edge;
  switch (loc.status) {
    case LocateStatus::InTriangle: return side(e) > 0 && side(lnext(e)) > 0 && side(lprev(e)) > 0;
    case LocateStatus::OnEdge: return side(e) == 0 && side(lnext(e)) > 0 && side(lprev(e)) > 0;
    case LocateStatus::OnVertex: return m.point(m.org(e)) == p;
    default: return false;
  }
}

Mesh delaunay_of(const std::vector<Point>& pts) {
  Mesh m = mesh_of(pts);
  Predicates pred;
  std::vector<std::pair<VertexId, VertexId>> dups;
  incremental_delaunay(m, pred, dups);
  return m;
}

// Queries: random points inside and around, every vertex, and edge midpoints of an integer grid
// (exactly on edges).
std::vector<Point> queries(const Mesh& m, unsigned seed) {
  std::vector<Point> q = uniform(400, seed, 1.4, -0.2);
  for (VertexId v{0}; v < m.vertex_count(); v = VertexId{v + 7}) q.push_back(m.point(v));
  return q;
}

}  // namespace

TEST(locate_agrees_with_brute_force_on_delaunay_meshes) {
  Predicates pred;
  const Mesh m = delaunay_of(uniform(1500, 31));
  std::mt19937 rng(5);
  int wrong = 0;
  for (const Point& p : queries(m, 32)) {
    const EdgeRef hint = static_cast<EdgeRef>(rng() % m.corner.size());
    if (!correct(m, p, locate(m, pred, p, hint))) ++wrong;
  }
  CHECK_EQ(wrong, 0);
}

TEST(locate_on_grid_edges_and_vertices) {
  Predicates pred;
  std::vector<Point> pts;
  for (int i = 0; i <= 10; ++i)
    for (int j = 0; j <= 10; ++j) pts.push_back({double(i), double(j)});
  const Mesh m = delaunay_of(pts);
  int wrong = 0, on_edge = 0, on_vertex = 0;
  for (int i = 0; i <= 20; ++i)
    for (int j = 0; j <= 20; ++j) {
      const Point p{i * 0.5, j * 0.5};
      const Location loc = locate(m, pred, p, EdgeRef{static_cast<std::uint32_t>((i * 37 + j * 11) % m.corner.size())});
      if (!correct(m, p, loc)) ++wrong;
      on_edge += loc.status == LocateStatus::OnEdge;
      on_vertex += loc.status == LocateStatus::OnVertex;
    }
  CHECK_EQ(wrong, 0);
  CHECK_EQ(on_vertex, 121);
  CHECK(on_edge >= 200);  // the horizontal and vertical half-points at least
}

TEST(locate_on_a_non_delaunay_mesh) {
  // Random flips spoil the Delaunay property, where plain visibility walks may circle.
  Predicates pred;
  Mesh m = delaunay_of(uniform(800, 33));
  std::mt19937 rng(6);
  for (int k = 0; k < 20000; ++k) {
    const EdgeRef e{static_cast<std::uint32_t>(rng() % m.corner.size())};
    const EdgeRef f = m.link[e];
    if (f == kNone) continue;
    const Point &a = m.point(m.org(e)), &b = m.point(m.dest(e)), &c = m.point(m.apex(e)), &d = m.point(m.apex(f));
    if (pred.orient2d(c, d, b) > 0 && pred.orient2d(d, c, a) > 0) flip(m, e);
  }
  REQUIRE(all_faults(m) == 0);
  CHECK(delaunay_faults(m) > 0);
  int wrong = 0;
  for (const Point& p : queries(m, 34))
    if (!correct(m, p, locate(m, pred, p, EdgeRef{static_cast<std::uint32_t>(rng() % m.corner.size())}))) ++wrong;
  CHECK_EQ(wrong, 0);
}

TEST(locate_across_a_notch_of_a_non_convex_mesh) {
  // A U shape of unit squares: columns 0 and 2 are two squares high, column 1 only one.
  std::vector<Point> pts;
  for (int j = 0; j <= 2; ++j)
    for (int i = 0; i <= 3; ++i) pts.push_back({double(i), double(j)});
  auto id = [](int i, int j) { return static_cast<VertexId>(j * 4 + i); };
  std::vector<Triple> tris;
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 3; ++i) {
      if (j == 1 && i == 1) continue;
      tris.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      tris.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  const Mesh m = make_mesh(pts, tris);
  Predicates pred;
  const EdgeRef left_top = edge_of(6_t, 0);  // a triangle of the left arm's upper square
  REQUIRE(m.point(m.corner[left_top]).y == 1.0 && m.point(m.corner[left_top]).x == 0.0);
  for (const Point& p : std::vector<Point>{{2.5, 1.5}, {2.2, 1.9}, {1.5, 1.5}, {1.5, 0.5}, {3.5, 1.5}}) {
    const Location loc = locate(m, pred, p, left_top);
    CHECK(correct(m, p, loc));
  }
  CHECK(locate(m, pred, {2.6, 1.5}, left_top).status == LocateStatus::InTriangle);
  CHECK(locate(m, pred, {1.5, 1.5}, left_top).status == LocateStatus::Outside);
}

TEST(locate_in_an_empty_mesh) {
  Predicates pred;
  Mesh m;
  CHECK(locate(m, pred, {0, 0}, kNone).status == LocateStatus::Outside);
  CHECK_EQ(locate(m, pred, {0, 0}, kNone).edge, kNone);
}
