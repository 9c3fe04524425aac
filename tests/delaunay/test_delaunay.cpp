// Delaunay triangulation tests. Every result is judged by facts computed independently of the
// triangulator (tests/mesh/mesh_checks.h): orientation and empty circles by exact predicates, the
// triangle count from Euler's formula with a monotone-chain hull, and agreement between algorithms.
#include <algorithm>
#include <cmath>
#include <random>

#include "delaunay/triangulate.h"
#include "harness/check.h"
#include "mesh/mesh_checks.h"

using namespace deltri;

namespace {

using meshcheck::hull_boundary_points;
using meshcheck::mesh_of;
using meshcheck::triangle_set;
using meshcheck::uniform;
using meshcheck::firm_edges;
using meshcheck::gaussian;
using meshcheck::shuffled_grid;

// Faults of a finished triangulation: the shared orientation, twin and empty-circle counts, plus
// what delaunay_triangulate promises on top: no dead slots, and exactly the Input vertices in use.
int faults(const Mesh& m, bool expect_triangles = true) {
  int bad = meshcheck::orientation_faults(m) + meshcheck::link_faults(m) + meshcheck::delaunay_faults(m);
  if (expect_triangles && m.triangle_slots() == 0) ++bad;
  std::vector<char> used(m.vertex_count(), 0);
  for (TriangleId t = 0; t < m.triangle_slots(); ++t) {
    if (!m.is_live(t)) { ++bad; continue; }
    for (unsigned i = 0; i < 3; ++i)
      if (m.corner[3 * t + i] < m.vertex_count()) used[m.corner[3 * t + i]] = 1;
  }
  for (VertexId v = 0; v < m.vertex_count(); ++v)
    if (expect_triangles && (m.kind[v] == VertexKind::Input) != (used[v] != 0)) ++bad;
  return bad;
}

void check_point_set(const std::vector<Point>& pts, DelaunayAlgorithm alg, int threads = 1) {
  Mesh m = mesh_of(pts);
  const DelaunayReport r = delaunay_triangulate(m, alg, threads);
  const std::size_t distinct = pts.size() - r.duplicates.size();
  const std::size_t h = hull_boundary_points(pts);
  CHECK_EQ(faults(m), 0);
  CHECK_EQ(static_cast<std::size_t>(m.live_triangles()), 2 * distinct - 2 - h);
}

}  // namespace

TEST(uniform_small_sizes) {
  for (std::size_t n = 3; n <= 40; ++n)
    for (unsigned seed = 0; seed < 20; ++seed) check_point_set(uniform(n, seed * 100 + n), DelaunayAlgorithm::DivideAndConquer);
}

TEST(uniform_large_alternating_and_vertical) {
  check_point_set(uniform(200000, 7), DelaunayAlgorithm::DivideAndConquer, 1);
  check_point_set(uniform(50000, 8), DelaunayAlgorithm::VerticalCuts, 1);
}

TEST(two_threads_give_identical_mesh) {
  const auto pts = uniform(150000, 9);
  Mesh a = mesh_of(pts), b = mesh_of(pts);
  delaunay_triangulate(a, DelaunayAlgorithm::DivideAndConquer, 1);
  delaunay_triangulate(b, DelaunayAlgorithm::DivideAndConquer, 2);
  CHECK(a.corner == b.corner);
  CHECK(a.link == b.link);
  CHECK_EQ(faults(b), 0);
}

TEST(grid_every_quad_cocircular) {
  std::vector<Point> pts;
  for (int i = 0; i < 120; ++i)
    for (int j = 0; j < 90; ++j) pts.push_back({i * 0.1, j * 0.1});
  std::shuffle(pts.begin(), pts.end(), std::mt19937(3));
  check_point_set(pts, DelaunayAlgorithm::DivideAndConquer);
  check_point_set(pts, DelaunayAlgorithm::VerticalCuts);
  Mesh m = mesh_of(pts);
  delaunay_triangulate(m, DelaunayAlgorithm::DivideAndConquer, 2);
  CHECK_EQ(m.live_triangles(), 2u * 119u * 89u);
}

TEST(small_grids_and_lines) {
  for (int w = 1; w <= 7; ++w)
    for (int h = 1; h <= 7; ++h) {
      std::vector<Point> pts;
      for (int i = 0; i < w; ++i)
        for (int j = 0; j < h; ++j) pts.push_back({double(i), double(j)});
      if (pts.size() < 3) continue;
      Mesh m = mesh_of(pts);
      delaunay_triangulate(m, DelaunayAlgorithm::DivideAndConquer, 1);
      const bool flat = w == 1 || h == 1;
      CHECK_EQ(faults(m, !flat), 0);
      CHECK_EQ(m.live_triangles(), flat ? 0u : 2u * (w - 1) * (h - 1));
    }
}

TEST(all_collinear_gives_no_triangles) {
  std::vector<Point> pts;
  for (int i = 0; i < 1000; ++i) pts.push_back({i * 0.5, 3.0 + i * 0.25});
  std::shuffle(pts.begin(), pts.end(), std::mt19937(4));
  Mesh m = mesh_of(pts);
  delaunay_triangulate(m, DelaunayAlgorithm::DivideAndConquer, 2);
  CHECK_EQ(m.live_triangles(), 0u);
  CHECK(std::ranges::equal(m.points, pts));
}

TEST(duplicates_keep_the_first_and_points_survive) {
  auto pts = uniform(5000, 11);
  for (int i = 0; i < 300; ++i) pts.push_back(pts[i * 7]);
  pts.push_back(pts[5]);
  Mesh m = mesh_of(pts);
  const DelaunayReport r = delaunay_triangulate(m, DelaunayAlgorithm::DivideAndConquer, 2);
  CHECK_EQ(r.duplicates.size(), 301u);
  CHECK(std::ranges::equal(m.points, pts));
  for (const auto& [dup, kept] : r.duplicates) {
    CHECK(dup > kept);
    CHECK(m.kind[dup] == VertexKind::Duplicate);
    CHECK(pts[dup] == pts[kept]);
  }
  CHECK_EQ(faults(m), 0);
  CHECK_EQ(static_cast<std::size_t>(m.live_triangles()), 2 * 5000 - 2 - hull_boundary_points(pts));
}

TEST(fewer_than_three_distinct_points) {
  Mesh m = mesh_of({{1, 1}, {1, 1}, {2, 2}});
  delaunay_triangulate(m, DelaunayAlgorithm::DivideAndConquer, 1);
  CHECK_EQ(m.live_triangles(), 0u);
}

TEST(huge_offset_and_tiny_scale) {
  check_point_set(uniform(20000, 12, 1.0, 1e9), DelaunayAlgorithm::DivideAndConquer);
  check_point_set(uniform(20000, 13, 1e-9, 0.0), DelaunayAlgorithm::DivideAndConquer);
  std::vector<Point> grid;
  for (int i = 0; i < 60; ++i)
    for (int j = 0; j < 60; ++j) grid.push_back({1e9 + i * 1e-7, 1e9 + j * 1e-7});
  check_point_set(grid, DelaunayAlgorithm::DivideAndConquer);
}

TEST(clusters_and_circle) {
  std::mt19937_64 rng(14);
  std::normal_distribution<double> g(0.0, 1e-3);
  std::vector<Point> pts;
  for (int c = 0; c < 50; ++c) {
    const double cx = c % 7, cy = c / 7;
    for (int i = 0; i < 400; ++i) pts.push_back({cx + g(rng), cy + g(rng)});
  }
  check_point_set(pts, DelaunayAlgorithm::DivideAndConquer, 2);
  std::vector<Point> circle;
  for (int i = 0; i < 2000; ++i) circle.push_back({std::cos(i * 0.0031415), std::sin(i * 0.0031415)});
  circle.push_back({0, 0});
  check_point_set(circle, DelaunayAlgorithm::DivideAndConquer);
}

TEST(divide_and_conquer_agrees_with_incremental) {
  for (unsigned seed = 0; seed < 5; ++seed) {
    const auto pts = uniform(3000, 100 + seed);
    Mesh a = mesh_of(pts), b = mesh_of(pts);
    delaunay_triangulate(a, DelaunayAlgorithm::DivideAndConquer, 1);
    delaunay_triangulate(b, DelaunayAlgorithm::Incremental, 1);
    CHECK(triangle_set(a) == triangle_set(b));
  }
}

// ---- Fortune's sweepline (-F) against divide and conquer ----
namespace {

// The sweepline's triangulation is Delaunay and, away from cocircular ties, the same as divide and
// conquer's; with no ties (`exact`) the same triangles.
void check_sweepline_matches(const std::vector<Point>& pts, bool exact) {
  Mesh a = mesh_of(pts), b = mesh_of(pts);
  const DelaunayReport ra = delaunay_triangulate(a, DelaunayAlgorithm::Sweepline, 1);
  const DelaunayReport rb = delaunay_triangulate(b, DelaunayAlgorithm::DivideAndConquer, 1);
  CHECK(!ra.sweepline_fell_back);
  CHECK(ra.duplicates == rb.duplicates);
  CHECK_EQ(faults(a, a.live_triangles() > 0), 0);
  CHECK_EQ(a.live_triangles(), b.live_triangles());
  if (exact) CHECK(triangle_set(a) == triangle_set(b));
  CHECK(firm_edges(a) == firm_edges(b));
}

}  // namespace

TEST(sweepline_small_sizes_and_degenerate_sets) {
  for (std::size_t n = 3; n <= 40; ++n)
    for (unsigned seed = 0; seed < 20; ++seed) check_point_set(uniform(n, seed * 100 + n), DelaunayAlgorithm::Sweepline);
  for (int w = 1; w <= 7; ++w)
    for (int h = 1; h <= 7; ++h)
      if (w * h >= 3) check_sweepline_matches(shuffled_grid(w, h, static_cast<unsigned>(w * 10 + h)), false);
  std::vector<Point> circle;
  for (int i = 0; i < 64; ++i) circle.push_back({std::cos(i * M_PI / 32), std::sin(i * M_PI / 32)});
  circle.push_back({0, 0});
  check_sweepline_matches(circle, false);
  check_sweepline_matches({{0, 0}, {1, 0}, {2, 0}, {3, 0}, {0, 0}}, false);  // collinear, a duplicate
}

// The ctest-sized version of `make bench`'s million-point comparison (tests/bench/sweepline_vs_dc).
TEST(sweepline_equals_divide_and_conquer_20k) {
  check_sweepline_matches(uniform(20000, 31), true);
  check_sweepline_matches(gaussian(20000, 32), true);
  check_sweepline_matches(shuffled_grid(141, 142, 33), false);
}
