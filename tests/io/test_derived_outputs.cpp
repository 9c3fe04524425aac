// Writers of the files derived from the triangulation: -o2 midpoints, -v, -g, and the physical
// groups of the .msh. Expected texts are worked out by hand on the two-triangle unit square.
#include "harness/check.h"
#include "io/midpoints.h"
#include "io/off_file.h"
#include "io/physical_groups.h"
#include "io/voronoi_file.h"
#include "io_test_util.h"

using namespace deltri;

namespace {

template <class F>
std::string written(F f) {
  std::string text;
  StringSink sink(text);
  f(sink);
  return text;
}

}  // namespace

TEST(voronoi_vertices_are_circumcentres_and_rays_point_out) {
  const Mesh m = iotest::two_triangles();
  // Both right triangles have the square's centre as circumcentre.
  CHECK_EQ(written([&](ByteSink& s) { write_voronoi_node_file(s, m, 1); }), "2 2 0 0\n1 0.5 0.5\n2 0.5 0.5\n");
  // Triangle 1 (0,1,2): side 0->1 on the bottom (ray down), 1->2 on the right (ray right), 2->0
  // shared with triangle 2; triangle 2 (0,2,3): 2->3 on top (up), 3->0 on the left (left).
  CHECK_EQ(written([&](ByteSink& s) { write_voronoi_edge_file(s, m, 1); }),
           "5 0\n1 1 -1 0 -1\n2 1 -1 1 0\n3 1 2\n4 2 -1 0 1\n5 2 -1 -1 0\n");
  CHECK_EQ(written([&](ByteSink& s) { write_voronoi_edge_file(s, m, 0); }),
           "5 0\n0 0 -1 0 -1\n1 0 -1 1 0\n2 0 1\n3 1 -1 0 1\n4 1 -1 -1 0\n");
}

TEST(voronoi_vertex_attributes_are_interpolated_at_the_circumcentre) {
  Mesh m = iotest::two_triangles();
  m.num_attributes = 1;
  m.attributes = {0, 2, 4, 6};  // a field that is not planar over the square
  // Triangle 1 (0,1,2) spans the plane a = 2x + 2y: 2 at the centre (0.5, 0.5). Triangle 2 (0,2,3)
  // through (0,0)=0, (1,1)=4, (0,1)=6: a = -2x + 6y, at the centre 2.
  CHECK_EQ(written([&](ByteSink& s) { write_voronoi_node_file(s, m, 1); }), "2 2 1 0\n1 0.5 0.5 2\n2 0.5 0.5 2\n");
}

TEST(off_is_zero_based_with_edge_count) {
  const Mesh m = iotest::two_triangles();
  CHECK_EQ(written([&](ByteSink& s) { write_off_file(s, m, nullptr); }),
           "OFF\n4 2 5\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n");
}

TEST(midpoints_one_per_edge_opposite_the_corners) {
  Mesh m = iotest::two_triangles();
  m.marker = {1, 1, 1, 1};
  m.num_attributes = 1;
  m.attributes = {0, 2, 4, 6};
  const std::vector<VertexId> mid = add_edge_midpoints(m);
  REQUIRE(m.vertex_count() == 9);  // four corners, five edges
  // Edges in .edge order: 0-1, 1-2, 2-0 (shared), then 2-3, 3-0.
  CHECK(m.points[4] == (Point{0.5, 0}));
  CHECK(m.points[5] == (Point{1, 0.5}));
  CHECK(m.points[6] == (Point{0.5, 0.5}));
  CHECK(m.points[7] == (Point{0.5, 1}));
  CHECK(m.points[8] == (Point{0, 0.5}));
  // Triangle 0 (0,1,2): opposite corner 0 is side 1-2, opposite 1 is 2-0, opposite 2 is 0-1.
  CHECK_EQ(mid[0], 5u);
  CHECK_EQ(mid[1], 6u);
  CHECK_EQ(mid[2], 4u);
  // Triangle 1 (0,2,3) shares the diagonal's midpoint, opposite its corner 2 (vertex 3).
  CHECK_EQ(mid[3], 7u);
  CHECK_EQ(mid[4], 8u);
  CHECK_EQ(mid[5], 6u);
  // Markers: boundary sides 1, the interior diagonal 0; attributes the mean of the ends.
  CHECK_EQ(m.marker[4], 1);
  CHECK_EQ(m.marker[6], 0);
  CHECK_EQ(m.attributes[6], 2.0);
  CHECK_EQ(m.attributes[7], 5.0);
  CHECK(m.kind[6] == VertexKind::Free);
  CHECK(m.kind[4] == VertexKind::Segment);
}

TEST(physical_groups_keep_positive_integer_markers_and_never_share_a_tag) {
  const MeshPhysicalGroups m = physical_groups({5, 0, 7, 5, 2.5, -1, 7}, {3, 1, 3}, true);
  const PhysicalGroups& g = m.lines;
  CHECK(g.values == (std::vector<double>{-1, 0, 2.5, 5, 7}));
  // -1 and 0 by rule 2 (2000000000 - m), 2.5 by rule 4 (the first tag from 1900000000).
  CHECK(g.tags == (std::vector<long long>{2000000001, 2000000000, 1900000000, 5, 7}));
  CHECK(g.group == (std::vector<std::uint32_t>{3, 1, 4, 3, 2, 0, 4}));
  // Attribute a is 1000000000 + a, apart from every marker's range.
  CHECK(m.surfaces.values == (std::vector<double>{1, 3}));
  CHECK(m.surfaces.tags == (std::vector<long long>{1000000001, 1000000003}));
  CHECK(m.surfaces.group == (std::vector<std::uint32_t>{1, 0, 1}));
  CHECK(m.clash.empty());
  CHECK_EQ(value_text(2.5), std::string("2.5"));
  CHECK_EQ(value_text(10), std::string("10"));
  // The default marker 1 on every boundary edge: the domain is not 1 too (GetDP's Region[1]).
  const MeshPhysicalGroups plain = physical_groups({1, 1, 1}, {0});
  CHECK(plain.lines.tags == (std::vector<long long>{1}));
  CHECK(plain.surfaces.tags == (std::vector<long long>{1000000000}));
  const MeshPhysicalGroups no_lines = physical_groups({}, {0});
  CHECK(no_lines.surfaces.tags == (std::vector<long long>{1000000000}));
}

TEST(physical_tags_do_not_move_when_another_marker_changes) {
  // Issue 46: a hole's marker 5 becomes 7; the domain and every other group keep their tags.
  const MeshPhysicalGroups before = physical_groups({1, 2, 3, 4, 5, 0}, {0});
  const MeshPhysicalGroups after = physical_groups({1, 2, 3, 4, 7, 0}, {0});
  CHECK(before.lines.tags == (std::vector<long long>{2000000000, 1, 2, 3, 4, 5}));
  CHECK(after.lines.tags == (std::vector<long long>{2000000000, 1, 2, 3, 4, 7}));
  CHECK(before.surfaces.tags == after.surfaces.tags);
  // With -A, attribute 10 is 1000000010 whatever the markers.
  CHECK(physical_groups({1, 5}, {10, 20}, true).surfaces.tags == (std::vector<long long>{1000000010, 1000000020}));
  CHECK(physical_groups({1, 9}, {10, 20}, true).surfaces.tags == (std::vector<long long>{1000000010, 1000000020}));
}

TEST(a_chosen_domain_tag_is_used_or_its_clash_named) {
  const MeshPhysicalGroups six = physical_groups({1, 2, 5}, {0}, false, 6);
  CHECK(six.surfaces.tags == (std::vector<long long>{6}));
  CHECK(six.clash.empty());
  const MeshPhysicalGroups five = physical_groups({1, 2, 5}, {0}, false, 5);
  CHECK_EQ(five.clash, std::string("tag 5 would be both marker 5's and the domain's"));
  // Under -A the chosen tag is the base: attributes 0 and 2 are 100 and 102.
  const MeshPhysicalGroups base = physical_groups({1, 102}, {0, 2}, true, 100);
  CHECK(base.surfaces.tags == (std::vector<long long>{100, 102}));
  CHECK_EQ(base.clash, std::string("tag 102 would be both marker 102's and attribute 2's"));
}

TEST(marker_groups_are_the_line_rule_alone) {
  // A surface in 3-D: facet markers -3, 0, 6, 5 (0 and -3 are no Gmsh tags: 2000000003 and 2000000000).
  const PhysicalGroups g = marker_groups({6, -3, 0, 5, 6});
  CHECK(g.values == (std::vector<double>{-3, 0, 5, 6}));
  CHECK(g.tags == (std::vector<long long>{2000000003, 2000000000, 5, 6}));
  CHECK(g.group == (std::vector<std::uint32_t>{3, 0, 1, 2, 3}));
}
