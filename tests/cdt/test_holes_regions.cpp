// Hole carving, convex hull enclosure, regional attributes/areas and boundary markers.
#include "cdt/convex_hull.h"
#include "cdt/holes_and_regions.h"
#include "cdt/markers.h"
#include "cdt_fixture.h"
#include "harness/id_literals.h"

using namespace cdt_test;

namespace {

// Outer square 0..3 (vertices 0-3) and inner square 1..2 (vertices 4-7).
std::vector<Point> nested_squares() {
  return {{0, 0}, {3, 0}, {3, 3}, {0, 3}, {1, 1}, {2, 1}, {2, 2}, {1, 2}};
}

std::vector<Pslg::Segment> nested_rings(int outer_marker = 0, int inner_marker = 0) {
  auto s = ring(0, 4, outer_marker);
  for (const auto& t : ring(4, 4, inner_marker)) s.push_back(t);
  return s;
}

}  // namespace

TEST(cdt_square_with_hole) {
  Built b;
  triangulate_and_insert(b, nested_squares(), nested_rings());
  const HoleReport h = carve_holes(b.mesh, b.pred, {{1.5, 1.5}}, false);
  CHECK(h.outside.empty());
  CHECK(h.on_segment.empty());
  CHECK(mesh_valid(b.mesh));
  CHECK(constrained_delaunay(b.mesh));
  CHECK(uncovered(b.mesh, {1.5, 1.5}));
  CHECK_NEAR(area(b.mesh), 8.0, 1e-14);
  CHECK_EQ(b.mesh.live_triangles(), 8u);
  CHECK_EQ(b.mesh.subsegments.size(), std::size_t{8});
  CHECK_EQ(live_edges_with_subsegment(b.mesh), std::size_t{8});
  for (std::uint32_t i = 0; i < 4; ++i) CHECK(collinear_chain(b.mesh, 4 + i, 4 + (i + 1) % 4));
}

TEST(cdt_concavity_and_dangling_segment_eaten) {
  Built b;
  // An L-shaped domain; a segment outside it ends up with no triangle on either side.
  std::vector<Point> pts{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}, {1.5, 1.5}, {1.9, 1.9}};
  auto segs = ring(0, 6);
  segs.push_back({6_v, 7_v, 0});
  triangulate_and_insert(b, pts, segs);
  const HoleReport h = carve_holes(b.mesh, b.pred, {}, false);
  CHECK_EQ(h.subsegments_removed, std::size_t{1});
  CHECK_EQ(b.mesh.subsegments.size(), std::size_t{6});
  CHECK(mesh_valid(b.mesh));
  CHECK_NEAR(area(b.mesh), 3.0, 1e-14);
  CHECK(uncovered(b.mesh, {1.5, 1.2}));
}

TEST(cdt_hole_outside_and_on_segment) {
  Built b;
  triangulate_and_insert(b, nested_squares(), nested_rings());
  const HoleReport h = carve_holes(b.mesh, b.pred, {{5, 5}, {1.5, 1.0}, {1, 1}, {-1, 1.5}}, false);
  CHECK_EQ(h.outside.size(), std::size_t{2});
  CHECK_EQ(h.on_segment.size(), std::size_t{2});
  CHECK_NEAR(area(b.mesh), 9.0, 1e-14);  // nothing carved but the (empty) outside
}

TEST(cdt_hole_point_carves_everything_in_only_region) {
  Built b;
  triangulate_and_insert(b, nested_squares(), ring(0, 4));
  carve_holes(b.mesh, b.pred, {{0.5, 0.5}}, false);
  CHECK_EQ(b.mesh.live_triangles(), 0u);
  CHECK(b.mesh.subsegments.empty());
}

TEST(cdt_convex_hull_switch) {
  Built b;
  // Open chain inside a point cloud: without -c everything would be eaten.
  std::vector<Point> pts{{0, 0}, {4, 0}, {4, 3}, {0, 3}, {2, 1.5}, {1, 1}, {3, 2}};
  triangulate_and_insert(b, pts, {{5, 6, 4}});
  const std::size_t added = enclose_convex_hull(b.mesh);
  CHECK_EQ(added, std::size_t{4});
  const HoleReport h = carve_holes(b.mesh, b.pred, {}, true);
  CHECK_EQ(h.triangles_removed, std::size_t{0});
  CHECK_NEAR(area(b.mesh), 12.0, 1e-14);
  CHECK(mesh_valid(b.mesh));
  int hull = 0;
  for (const auto& s : b.mesh.subsegments)
    if (s.segment == kNone) hull += s.marker == 1;
  CHECK_EQ(hull, 4);
  CHECK(collinear_chain(b.mesh, 5, 6));
  CHECK(chain_of_segment(b.mesh, 0, 5, 6));
  // Without -c the same input is eaten whole (an unclosed boundary).
  Built c;
  triangulate_and_insert(c, pts, {{5, 6, 4}});
  carve_holes(c.mesh, c.pred, {}, false);
  CHECK_EQ(c.mesh.live_triangles(), 0u);
}

TEST(cdt_regions_attributes_and_areas) {
  Built b;
  auto segs = nested_rings();
  triangulate_and_insert(b, nested_squares(), segs);
  carve_holes(b.mesh, b.pred, {}, false);
  const std::vector<Pslg::Region> regions{
      {{0.5, 0.5}, 1.0, 0.25},  // the ring between the squares
      {{1.5, 1.5}, 2.0, -1.0},  // the inner square
      {{1.2, 1.8}, 3.0, 0.5},   // the inner square again: overrides the previous one
      {{9, 9}, 4.0, 1.0},       // outside: ignored
  };
  spread_regions(b.mesh, b.pred, regions, true, true);
  REQUIRE(b.mesh.num_triangle_attributes == 1);
  REQUIRE(b.mesh.triangle_attributes.size() == b.mesh.triangle_slots());
  REQUIRE(b.mesh.area_bound.size() == b.mesh.triangle_slots());
  Predicates p;
  for (TriangleId t{0}; t < b.mesh.triangle_slots(); ++t) {
    const Point &a = b.mesh.point(b.mesh.corner[edge_of(t, 0)]), &c = b.mesh.point(b.mesh.corner[edge_of(t, 1)]),
                &d = b.mesh.point(b.mesh.corner[edge_of(t, 2)]);
    const Point centroid{(a.x + c.x + d.x) / 3, (a.y + c.y + d.y) / 3};
    const bool inner = centroid.x > 1 && centroid.x < 2 && centroid.y > 1 && centroid.y < 2;
    CHECK_EQ(b.mesh.triangle_attributes[t], inner ? 3.0 : 1.0);
    CHECK_EQ(b.mesh.area_bound[t], inner ? 0.5 : 0.25);
  }
}

TEST(cdt_region_attribute_zero_outside_regions) {
  Built b;
  triangulate_and_insert(b, nested_squares(), nested_rings());
  carve_holes(b.mesh, b.pred, {}, false);
  spread_regions(b.mesh, b.pred, {{{1.5, 1.5}, 5.0, -1.0}}, true, false);
  CHECK(b.mesh.area_bound.empty());
  double sum = 0;
  for (const double a : b.mesh.triangle_attributes) sum += a;
  CHECK_EQ(sum, 10.0);  // the two inner triangles
}

TEST(cdt_boundary_markers) {
  Built b;
  auto pts = nested_squares();
  pts.push_back({1.5, 0.5});  // interior vertex
  pts.push_back({1.5, 0});    // on the outer bottom segment
  auto segs = nested_rings(0, 0);
  segs[0].marker = 5;  // bottom of the outer square
  triangulate_and_insert(b, pts, segs);
  b.mesh.marker.assign(b.mesh.vertex_count(), 0);
  b.mesh.marker[3] = 9;  // an input marker on a corner
  carve_holes(b.mesh, b.pred, {{1.5, 1.5}}, false);
  assign_boundary_markers(b.mesh, true);
  REQUIRE(b.mesh.marker.size() == 10u);
  CHECK_EQ(b.mesh.marker[0], 5);
  CHECK_EQ(b.mesh.marker[1], 5);
  CHECK_EQ(b.mesh.marker[9], 5);
  CHECK_EQ(b.mesh.marker[2], 1);
  CHECK_EQ(b.mesh.marker[3], 9);
  for (VertexId v{4}; v < 8; ++v) CHECK_EQ(b.mesh.marker[v], 1);  // hole boundary
  CHECK_EQ(b.mesh.marker[8], 0);
  // Without input markers the stored corner marker is ignored.
  assign_boundary_markers(b.mesh, false);
  CHECK_EQ(b.mesh.marker[3], 1);
}
