// absorb_near_hull_vertices: vertices within an ulp or so of a hull edge join the hull chain.
#include <cmath>
#include <vector>

#include "cdt/convex_hull.h"
#include "cdt_fixture.h"
#include "harness/check.h"
#include "harness/id_literals.h"

using namespace deltri;
using namespace cdt_test;

namespace {

// Does some boundary edge (no twin) carrying a subsegment leave v?
bool on_hull_chain(const Mesh& m, std::uint32_t v) {
  for (EdgeRef e{0}; e < m.corner.size(); ++e)
    if (m.corner[e] != kNone && m.link[e] == kNone && m.subseg.has(e) && m.org(e) == v) return true;
  return false;
}

double mesh_area(const Mesh& m) {
  double area = 0.0;
  for (TriangleId t{0}; t < m.triangle_slots(); ++t) {
    if (!m.is_live(t)) continue;
    const Point& a = m.point(m.corner[edge_of(t, 0)]);
    const Point& b = m.point(m.corner[edge_of(t, 1)]);
    const Point& c = m.point(m.corner[edge_of(t, 2)]);
    area += 0.5 * ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
  }
  return area;
}

}  // namespace

// Vertex 3 lies on x + y = 100 in decimal and a fraction of an ulp inside it in doubles; vertex 4
// lies 1e-11 (some 10^5 ulps) inside the bottom edge, which refinement can mesh.
TEST(cdt_absorb_takes_a_vertex_an_ulp_inside_the_hull_into_its_chain) {
  Built b;
  triangulate_and_insert(b, {{0, 0}, {100, 0}, {0, 100}, {10.127463299999999, 89.8725367}, {20, 1e-11}, {30, 30}}, {});
  enclose_convex_hull(b.mesh);
  const std::size_t hull_subsegments = b.mesh.subsegments.size();
  const double area = mesh_area(b.mesh);
  const std::uint32_t triangles = b.mesh.live_triangles();
  CHECK(!on_hull_chain(b.mesh, 3));
  CHECK_EQ(absorb_near_hull_vertices(b.mesh, b.pred), std::size_t{1});
  CHECK(mesh_valid(b.mesh));
  CHECK(on_hull_chain(b.mesh, 3));
  CHECK(!on_hull_chain(b.mesh, 4));
  CHECK_EQ(b.mesh.subsegments.size(), hull_subsegments + 1);
  CHECK_EQ(b.mesh.live_triangles(), triangles - 1);
  // The sliver left out is less than an ulp thick.
  CHECK(std::fabs(mesh_area(b.mesh) - area) < 1e-12);
  for (const Subsegment& s : b.mesh.subsegments) CHECK_EQ(s.marker, 1);
  // Nothing more to take: a second call changes nothing.
  CHECK_EQ(absorb_near_hull_vertices(b.mesh, b.pred), std::size_t{0});
}

// robustness4.node's first row: a rotated grid whose side points lie within an ulp of the hull
// edge through the corners; all four are taken, one after another along the chain.
TEST(cdt_absorb_follows_a_chain_of_near_hull_vertices) {
  const std::vector<Point> row{{-3.0381276552207055, 10.481881920449052}, {-2.1931270567413446, 11.016647278872279},
                               {-1.3481264582619854, 11.551412637295508}, {-0.5031258597826245, 12.086177995718735},
                               {0.3418747386967347, 12.620943354141964},  {1.1868753371760938, 13.155708712565193},
                               {-0.3643008631045621, 6.256878928052252}};
  Built b;
  triangulate_and_insert(b, row, {});
  enclose_convex_hull(b.mesh);
  const std::size_t absorbed = absorb_near_hull_vertices(b.mesh, b.pred);
  CHECK(mesh_valid(b.mesh));
  std::size_t on_chain = 0;
  for (VertexId v{1}; v <= 4; ++v) on_chain += on_hull_chain(b.mesh, v);
  CHECK_EQ(on_chain, std::size_t{4});
  CHECK(absorbed >= 1);
}

// A vertex well inside (a millionth of the edge) stays where it is.
TEST(cdt_absorb_leaves_ordinary_vertices_alone) {
  Built b;
  triangulate_and_insert(b, {{0, 0}, {1, 0}, {0.5, 1e-6}, {0.5, 1}}, {});
  enclose_convex_hull(b.mesh);
  CHECK_EQ(absorb_near_hull_vertices(b.mesh, b.pred), std::size_t{0});
  CHECK(!on_hull_chain(b.mesh, 2));
}
