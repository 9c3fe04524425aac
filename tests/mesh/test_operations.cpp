// flip, split_triangle and split_edge on small hand-built meshes.
#include <stdexcept>

#include "harness/check.h"
#include "harness/id_literals.h"
#include "mesh/operations.h"
#include "mesh_checks.h"

using namespace deltri;
using namespace meshcheck;

TEST(flip_replaces_the_diagonal) {
  Mesh m = unit_square();
  const EdgeRef e = find_edge(m, 0, 2);
  REQUIRE(e != kNone);
  const EdgeRef g = flip(m, e);
  CHECK_EQ(m.org(g), 3u);  // old apex of 0->2 (in triangle 0,2,3) to the apex of its twin
  CHECK_EQ(m.dest(g), 1u);
  CHECK_EQ(all_faults(m), 0);
  CHECK_EQ(euler_characteristic(m), 1);
  CHECK(triangle_set(m) == (std::vector<Triple>{{0, 1, 3}, {1, 2, 3}}));
  CHECK(find_edge(m, 0, 2) == kNone);
  flip(m, g);
  CHECK(triangle_set(m) == (std::vector<Triple>{{0, 1, 2}, {0, 2, 3}}));
  CHECK_EQ(all_faults(m), 0);
}

// flip's refusal of a boundary edge or a subsegment: tests/mesh_checked (built with the checks on).

TEST(flip_inside_a_mesh_keeps_outer_links_and_subsegments) {
  // A hexagon fan around a centre vertex 6; flipping a spoke touches four outer neighbours.
  std::vector<Point> pts{{2, 0}, {1, 1.7}, {-1, 1.7}, {-2, 0}, {-1, -1.7}, {1, -1.7}, {0, 0.1}};
  std::vector<Triple> tris;
  for (VertexId i{0}; i < 6; ++i) tris.push_back({i, (i + 1) % 6, 6});
  Mesh m = make_mesh(pts, tris);
  m.enable_subsegments();
  m.subsegments.push_back({1_v, 2_v, 4, 0});
  m.set_subsegment(find_edge(m, 1, 2), 0_s);
  const EdgeRef g = flip(m, find_edge(m, 6, 1));
  CHECK_EQ(m.org(g), 2u);
  CHECK_EQ(m.dest(g), 0u);
  CHECK_EQ(all_faults(m), 0);
  CHECK_EQ(euler_characteristic(m), 1);
  const EdgeRef s = find_edge(m, 1, 2);
  REQUIRE(s != kNone);
  CHECK_EQ(m.subseg[s], 0u);
  CHECK_EQ(m.link[s], kNone);
  int carrying = 0;
  for (EdgeRef e{0}; e < m.corner.size(); ++e) carrying += m.subseg.has(e);
  CHECK_EQ(carrying, 1);
}

TEST(split_triangle_makes_three_and_copies_region_data) {
  Mesh m = make_mesh({{0, 0}, {4, 0}, {0, 4}}, {{0, 1, 2}});
  m.num_triangle_attributes = 2;
  m.triangle_attributes = {7.5, -1.0};
  m.area_bound = {0.25};
  const VertexId v = m.add_vertex({1, 1}, VertexKind::Free);
  const EdgeRef out = split_triangle(m, 0_e, v);
  CHECK_EQ(m.org(out), v);
  CHECK_EQ(m.live_triangles(), 3u);
  CHECK_EQ(all_faults(m), 0);
  CHECK_EQ(euler_characteristic(m), 1);
  CHECK(triangle_set(m) == (std::vector<Triple>{{0, 1, 3}, {0, 3, 2}, {1, 2, 3}}));
  REQUIRE(m.triangle_attributes.size() == 6u);
  REQUIRE(m.area_bound.size() == 3u);
  for (TriangleId t{0}; t < 3; ++t) {
    CHECK_EQ(m.triangle_attributes[2 * t], 7.5);
    CHECK_EQ(m.triangle_attributes[2 * t + 1], -1.0);
    CHECK_EQ(m.area_bound[t], 0.25);
  }
}

TEST(split_triangle_reuses_dead_slots) {
  Mesh m = make_mesh({{0, 0}, {4, 0}, {0, 4}, {5, 5}}, {{0, 1, 2}, {1, 3, 2}});
  m.kill_triangle(1_t);
  const VertexId v = m.add_vertex({1, 1}, VertexKind::Free);
  split_triangle(m, 0_e, v);
  CHECK_EQ(m.triangle_slots(), 3u);
  CHECK_EQ(m.live_triangles(), 3u);
  CHECK_EQ(all_faults(m), 0);
}

TEST(split_interior_edge_without_subsegment) {
  Mesh m = unit_square();
  const VertexId v = m.add_vertex({0.5, 0.5}, VertexKind::Free);
  const EdgeRef out = split_edge(m, find_edge(m, 2, 0), v);
  CHECK_EQ(m.org(out), v);
  CHECK_EQ(m.live_triangles(), 4u);
  CHECK_EQ(all_faults(m), 0);
  CHECK_EQ(euler_characteristic(m), 1);
  CHECK(triangle_set(m) == (std::vector<Triple>{{0, 1, 4}, {0, 4, 3}, {1, 2, 4}, {2, 3, 4}}));
}

TEST(split_edge_splits_its_subsegment) {
  Mesh m = unit_square();
  m.enable_subsegments();
  m.subsegments.push_back({2_v, 0_v, 9, 3});  // stored against the edge's direction on purpose
  m.set_subsegment(find_edge(m, 0, 2), 0_s);
  const VertexId v = m.add_vertex({0.5, 0.5}, VertexKind::Segment);
  split_edge(m, find_edge(m, 0, 2), v);
  CHECK_EQ(all_faults(m), 0);
  REQUIRE(m.subsegments.size() == 2u);
  // The old record keeps its first endpoint; the new one covers the rest.
  CHECK_EQ(m.subsegments[0].a, 2u);
  CHECK_EQ(m.subsegments[0].b, v);
  CHECK_EQ(m.subsegments[1].a, v);
  CHECK_EQ(m.subsegments[1].b, 0u);
  for (const Subsegment& s : m.subsegments) {
    CHECK_EQ(s.marker, 9);
    CHECK_EQ(s.segment, 3u);
  }
  CHECK_EQ(m.subseg[find_edge(m, 2, v)], 0u);
  CHECK_EQ(m.subseg[find_edge(m, v, 2)], 0u);
  CHECK_EQ(m.subseg[find_edge(m, 0, v)], 1u);
  CHECK_EQ(m.subseg[find_edge(m, v, 0)], 1u);
  int carrying = 0;
  for (EdgeRef e{0}; e < m.corner.size(); ++e) carrying += m.subseg.has(e);
  CHECK_EQ(carrying, 4);
}

TEST(split_boundary_edge) {
  Mesh m = unit_square();
  m.area_bound = {0.5, 0.125};
  const VertexId v = m.add_vertex({0.5, 0}, VertexKind::Segment);
  const EdgeRef out = split_edge(m, find_edge(m, 0, 1), v);
  CHECK_EQ(m.org(out), v);
  CHECK_EQ(m.live_triangles(), 3u);
  CHECK_EQ(all_faults(m), 0);
  CHECK_EQ(euler_characteristic(m), 1);
  CHECK(triangle_set(m) == (std::vector<Triple>{{0, 2, 3}, {0, 4, 2}, {1, 2, 4}}));
  CHECK_EQ(m.link[find_edge(m, 0, v)], kNone);
  CHECK_EQ(m.link[find_edge(m, v, 1)], kNone);
  CHECK_EQ(m.area_bound[m.triangle_slots() - 1], 0.5);
}

// refine/refine_in_parts.cpp refines parts cut off with part_with: the part holds only the vertices and
// subsegment records it is given, renumbered in their order (record endpoints too), and keeps room
// for what the part adds (the whole mesh's reserved vertex room, a quarter more records), since a
// copy of exactly its size reallocated at the first addition and the abandoned copy stayed
// resident (the 50x50 holes' peak). Same contents, no reallocation.
TEST(part_with_copies_the_given_vertices_with_room_to_grow) {
  Mesh m = unit_square();
  m.marker.assign(m.vertex_count(), 3);
  m.marker[3] = 7;
  m.points.reserve(1000);
  m.kind.reserve(1000);
  for (SubsegmentId s{0}; s < 40; ++s) m.subsegments.push_back({s % 2 ? 1_v : 3_v, 3_v, 5, s});
  std::vector<SubsegmentId> records;
  for (std::uint32_t s = 0; s < 40; s += 2) records.push_back(SubsegmentId{s});
  Mesh part = m.part_with({1_v, 3_v}, records);
  CHECK_EQ(part.vertex_count(), 2u);
  CHECK(part.points[0] == m.points[1] && part.points[1] == m.points[3]);
  CHECK(part.kind[1] == m.kind[3]);
  CHECK_EQ(part.marker[1], 7);
  CHECK_EQ(part.subsegments.size(), 20u);
  CHECK_EQ(part.subsegments[19].segment, 38u);
  CHECK_EQ(part.subsegments[19].a, 1u);  // vertex 3 of the mesh
  CHECK_EQ(part.subsegments[19].b, 1u);
  CHECK_EQ(part.triangle_slots(), 0u);
  const Point* points = part.points.data();
  const VertexKind* kind = part.kind.data();
  const int* marker = part.marker.data();
  const Subsegment* records_data = part.subsegments.data();
  for (int i = 0; i < 900; ++i) part.add_vertex({0.5, 0.001 * i}, VertexKind::Free);
  for (SubsegmentId s{0}; s < 5; ++s) part.subsegments.push_back({1_v, 2_v, 0, s});
  CHECK(part.points.data() == points);
  CHECK(part.kind.data() == kind);
  CHECK(part.marker.data() == marker);
  CHECK(part.subsegments.data() == records_data);
  CHECK_EQ(part.marker.size(), part.vertex_count());
}
