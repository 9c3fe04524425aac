// Statistics on triangles whose measures are known in closed form.
#include <cmath>
#include <numeric>
#include <string>

#include "harness/check.h"
#include "harness/id_literals.h"
#include "quality/mesh_builders.h"
#include "quality/statistics.h"

using namespace deltri;
using namespace quality_test;

namespace {

template <std::size_t N>
std::uint64_t sum(const std::array<std::uint64_t, N>& a) {
  return std::accumulate(a.begin(), a.end(), std::uint64_t{0});
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

}  // namespace

TEST(right_isosceles_triangle) {
  Mesh m = mesh_of({{0, 0}, {1, 0}, {0, 1}});
  m.add_triangle(0_v, 1_v, 2_v);
  const MeshStatistics s = compute_statistics(m);
  CHECK_EQ(s.vertices, 3u);
  CHECK_EQ(s.vertices_in_triangles, 3u);
  CHECK_EQ(s.triangles, 1u);
  CHECK_EQ(s.edges, 3u);
  CHECK_EQ(s.exterior_boundary_edges, 3u);
  CHECK_EQ(s.interior_boundary_edges, 0u);
  CHECK_EQ(s.subsegments, 0u);
  CHECK_EQ(s.smallest_area, 0.5);
  CHECK_EQ(s.largest_area, 0.5);
  CHECK_EQ(s.shortest_edge, 1.0);
  CHECK_EQ(s.longest_edge, std::sqrt(2.0));
  CHECK_NEAR(s.shortest_altitude, std::sqrt(0.5), 1e-15);
  CHECK_EQ(s.largest_aspect_ratio, 2.0);  // sqrt(2) / sqrt(1/2)
  CHECK_NEAR(s.smallest_angle, 45.0, 1e-12);
  CHECK_NEAR(s.largest_angle, 90.0, 1e-12);
  CHECK_EQ(s.angle_histogram[4], 2u);                             // both 45s in 40-50
  CHECK_EQ(s.angle_histogram[8] + s.angle_histogram[9], 1u);      // 90, whichever side it rounds
  CHECK_EQ(s.angle_histogram_fine[44] + s.angle_histogram_fine[45], 2u);
  CHECK_EQ(sum(s.angle_histogram), 3u);
  CHECK_EQ(sum(s.angle_histogram_fine), 3u);
  CHECK_EQ(s.aspect_histogram[2], 1u);  // exactly 2 opens the bin [2, 2.5)
  CHECK_EQ(sum(s.aspect_histogram), 1u);
}

TEST(equilateral_triangle) {
  const double h = std::sqrt(3.0) / 2.0;
  Mesh m = mesh_of({{0, 0}, {1, 0}, {0.5, h}});
  m.add_triangle(0_v, 1_v, 2_v);
  const MeshStatistics s = compute_statistics(m);
  CHECK_NEAR(s.smallest_area, std::sqrt(3.0) / 4.0, 1e-15);
  CHECK_NEAR(s.largest_area, std::sqrt(3.0) / 4.0, 1e-15);
  CHECK_NEAR(s.shortest_edge, 1.0, 1e-15);
  CHECK_NEAR(s.longest_edge, 1.0, 1e-15);
  CHECK_NEAR(s.shortest_altitude, h, 1e-15);
  CHECK_NEAR(s.largest_aspect_ratio, 2.0 / std::sqrt(3.0), 1e-14);
  CHECK_NEAR(s.smallest_angle, 60.0, 1e-12);
  CHECK_NEAR(s.largest_angle, 60.0, 1e-12);
  CHECK_EQ(s.angle_histogram[5] + s.angle_histogram[6], 3u);
  CHECK_EQ(s.aspect_histogram[0], 1u);
}

TEST(counts_on_a_segmented_square_with_a_dead_slot) {
  // The diamond with a subsegment on its diagonal (interior boundary) and on edge a->b
  // (exterior), plus an unused duplicate vertex and a killed third triangle.
  Mesh m = diamond_short_diagonal();
  m.add_vertex({0, 1}, VertexKind::Duplicate);
  m.enable_subsegments();
  m.subsegments = {{1_v, 3_v, 1, 0}, {0_v, 1_v, 2, 1}};
  m.set_subsegment(1_e, 0_s);
  m.set_subsegment(0_e, 1_s);
  const TriangleId extra = m.add_triangle(0_v, 1_v, 2_v);
  m.kill_triangle(extra);
  const MeshStatistics s = compute_statistics(m);
  CHECK_EQ(s.vertices, 4u);
  CHECK_EQ(s.vertices_in_triangles, 4u);
  CHECK_EQ(s.triangles, 2u);
  CHECK_EQ(s.edges, 5u);
  CHECK_EQ(s.exterior_boundary_edges, 4u);
  CHECK_EQ(s.interior_boundary_edges, 1u);
  CHECK_EQ(s.subsegments, 2u);
  CHECK_EQ(s.smallest_area, 2.0);  // each half of the diamond: base 2 (b-d), height 2
  CHECK_EQ(s.largest_area, 2.0);
  CHECK_EQ(s.shortest_edge, 2.0);           // b-d
  CHECK_EQ(s.longest_edge, std::sqrt(5.0));  // the four sides
  CHECK_EQ(sum(s.angle_histogram), 6u);
}

TEST(fan_counts_and_angles) {
  const MeshStatistics s = compute_statistics(square_fan());
  CHECK_EQ(s.triangles, 8u);
  CHECK_EQ(s.edges, 16u);
  CHECK_EQ(s.exterior_boundary_edges, 8u);
  CHECK_EQ(s.smallest_area, 0.5);
  CHECK_EQ(s.largest_area, 0.5);
  CHECK_NEAR(s.smallest_angle, 45.0, 1e-12);
  CHECK_NEAR(s.largest_angle, 90.0, 1e-12);
  CHECK_EQ(s.angle_histogram[4], 16u);
}

TEST(flat_triangle_has_infinite_aspect_ratio) {
  Mesh m = mesh_of({{0, 0}, {1, 0}, {2, 0}});
  m.add_triangle(0_v, 1_v, 2_v);
  const MeshStatistics s = compute_statistics(m);
  CHECK(std::isinf(s.largest_aspect_ratio));
  CHECK_EQ(s.aspect_histogram[kAspectBins - 1], 1u);
  CHECK_EQ(s.smallest_area, 0.0);
  CHECK_EQ(s.shortest_altitude, 0.0);
  CHECK_NEAR(s.smallest_angle, 0.0, 1e-12);
  CHECK_NEAR(s.largest_angle, 180.0, 1e-12);
  CHECK_EQ(s.angle_histogram[0], 2u);
  CHECK_EQ(s.angle_histogram[17], 1u);  // 180 belongs to the last bin
  CHECK_EQ(s.angle_histogram_fine[179], 1u);
}

TEST(format_lists_counts_and_histograms) {
  Mesh m = mesh_of({{0, 0}, {1, 0}, {0, 1}});
  m.add_triangle(0_v, 1_v, 2_v);
  const std::string text = format_statistics(compute_statistics(m));
  CHECK(contains(text, "Mesh triangles: 1\n"));
  CHECK(contains(text, "Mesh edges: 3\n"));
  CHECK(contains(text, "largest 2\n"));
  CHECK(contains(text, "1.5 - 2"));
  CHECK(contains(text, ">= 100000"));
  CHECK(contains(text, "170 - 180"));
  CHECK(text.back() == '\n');
}

TEST(format_of_an_empty_mesh) {
  const MeshStatistics s = compute_statistics(Mesh{});
  CHECK_EQ(s.triangles, 0u);
  CHECK_EQ(s.smallest_angle, 0.0);
  const std::string text = format_statistics(s);
  CHECK(contains(text, "Mesh triangles: 0\n"));
  CHECK(contains(text, "No triangles"));
  CHECK(!contains(text, "histogram"));
}
