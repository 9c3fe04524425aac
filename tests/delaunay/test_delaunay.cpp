// Delaunay triangulation tests. Every result is judged by facts computed independently of the
// triangulator (tests/mesh/mesh_checks.h): orientation and empty circles by exact predicates, the
// triangle count from Euler's formula with a monotone-chain hull, and agreement between algorithms.
#include <algorithm>
#include <cmath>
#include <random>

#include "delaunay/triangulate.h"
#include "geometry/exact_reference.h"
#include "harness/check.h"
#include "mesh/mesh_checks.h"

using namespace deltri;

namespace {

using meshcheck::hull_boundary_points;
using meshcheck::mesh_of;
using meshcheck::triangle_set;
using meshcheck::uniform;
using meshcheck::gaussian;
using meshcheck::shuffled_grid;

// Faults of a finished triangulation: the shared orientation, twin and empty-circle counts, plus
// what delaunay_triangulate promises on top: no dead slots, and exactly the Input vertices in use.
int faults(const Mesh& m, bool expect_triangles = true) {
  int bad = meshcheck::orientation_faults(m) + meshcheck::link_faults(m) + meshcheck::delaunay_faults(m);
  if (expect_triangles && m.triangle_slots() == 0) ++bad;
  std::vector<char> used(m.vertex_count(), 0);
  for (TriangleId t{0}; t < m.triangle_slots(); ++t) {
    if (!m.is_live(t)) { ++bad; continue; }
    for (unsigned i = 0; i < 3; ++i)
      if (m.corner[3 * t + i] < m.vertex_count()) used[m.corner[3 * t + i]] = 1;
  }
  for (VertexId v{0}; v < m.vertex_count(); ++v)
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

// ---- one triangulation, ties included: every algorithm against the perturbed reference ----
namespace {

// Interior edges that are not locally Delaunay under the symbolic perturbation, judged by the
// independent reference (tests/geometry/exact_reference.h). None, in a triangulation of the convex
// hull of the points, makes it the perturbed points' Delaunay triangulation, which is unique.
int perturbed_faults(const Mesh& m) {
  int bad = 0;
  for (EdgeRef e{0}; e < m.corner.size(); ++e) {
    if (!m.is_live(triangle_of(e)) || m.link[e] == kNone || m.link[e] < e) continue;
    if (reference::perturbed_incircle_sign(m.point(m.org(e)), m.point(m.dest(e)), m.point(m.apex(e)),
                                           m.point(m.apex(m.link[e]))) >= 0)
      ++bad;
  }
  return bad;
}

// Divide and conquer (one and two threads, alternating and vertical cuts), the sweepline and
// incremental insertion give the same triangles; with `reference` those are also checked against
// the exact perturbed test (slow: arbitrary-precision 4x4 determinants).
void check_one_triangulation(const std::vector<Point>& pts, bool reference) {
  Mesh dc = mesh_of(pts);
  const DelaunayReport rdc = delaunay_triangulate(dc, DelaunayAlgorithm::DivideAndConquer, 1);
  const bool flat = dc.live_triangles() == 0;
  CHECK_EQ(faults(dc, !flat), 0);
  CHECK_EQ(static_cast<std::size_t>(dc.live_triangles()),
           flat ? 0 : 2 * (pts.size() - rdc.duplicates.size()) - 2 - hull_boundary_points(pts));
  if (reference) CHECK_EQ(perturbed_faults(dc), 0);
  const auto expected = triangle_set(dc);
  for (const auto& [algorithm, threads] : {std::pair{DelaunayAlgorithm::DivideAndConquer, 2}, std::pair{DelaunayAlgorithm::VerticalCuts, 1},
                                           std::pair{DelaunayAlgorithm::Sweepline, 1}, std::pair{DelaunayAlgorithm::Incremental, 1}}) {
    Mesh m = mesh_of(pts);
    const DelaunayReport r = delaunay_triangulate(m, algorithm, threads);
    CHECK(!r.sweepline_fell_back);
    CHECK(r.duplicates == rdc.duplicates);
    CHECK_EQ(faults(m, !flat), 0);
    CHECK(triangle_set(m) == expected);
  }
}

std::vector<Point> regular_polygon(int n, double radius, Point centre, bool with_centre) {
  std::vector<Point> pts;
  for (int i = 0; i < n; ++i)
    pts.push_back({centre.x + radius * std::cos(2 * M_PI * i / n), centre.y + radius * std::sin(2 * M_PI * i / n)});
  if (with_centre) pts.push_back(centre);
  return pts;
}

// A polygon symmetric about both axes and both diagonals exactly (mirrored doubles), so that any
// two mirror pairs are exactly cocircular, on circles of several radii.
std::vector<Point> mirrored_rings(int per_octant, int rings) {
  std::vector<Point> pts{{0, 0}};
  for (int r = 1; r <= rings; ++r)
    for (int i = 0; i < per_octant; ++i) {
      const double angle = (i + 0.5 * (r % 2)) * M_PI / (4 * per_octant);
      const double x = r * std::cos(angle), y = r * std::sin(angle);
      for (const Point p : {Point{x, y}, Point{y, x}})
        for (const Point s : {Point{1, 1}, Point{-1, 1}, Point{1, -1}, Point{-1, -1}}) pts.push_back({s.x * p.x, s.y * p.y});
    }
  return pts;
}

// The lattice points on circles x^2 + y^2 = r^2 with many representations (exactly cocircular).
std::vector<Point> lattice_circles(std::initializer_list<int> radii, Point centre) {
  std::vector<Point> pts;
  for (const int r : radii)
    for (int x = -r; x <= r; ++x)
      for (int y = -r; y <= r; ++y)
        if (x * x + y * y == r * r) pts.push_back({centre.x + x, centre.y + y});
  pts.push_back(centre);
  return pts;
}

// A random subset of a w x h lattice, with some points repeated.
std::vector<Point> lattice_subset(int w, int h, double keep, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Point> pts;
  for (int i = 0; i < w; ++i)
    for (int j = 0; j < h; ++j)
      if (u(rng) < keep) pts.push_back({i * 0.5, j * 0.5});
  for (std::size_t k = 0; k < pts.size(); k += 17) pts.push_back(pts[k]);
  std::shuffle(pts.begin(), pts.end(), rng);
  return pts;
}

}  // namespace

TEST(one_triangulation_on_grids_and_lines) {
  for (int w = 1; w <= 9; ++w)
    for (int h = 1; h <= 9; ++h)
      if (w * h >= 3) check_one_triangulation(shuffled_grid(w, h, static_cast<unsigned>(w * 10 + h)), true);
  check_one_triangulation({{0, 0}, {1, 0}, {2, 0}, {3, 0}, {0, 0}}, true);  // collinear, a duplicate
  std::vector<Point> far_grid;
  for (int i = 0; i < 30; ++i)
    for (int j = 0; j < 20; ++j) far_grid.push_back({1e9 + i * 1e-7, -1e9 + j * 1e-7});
  std::shuffle(far_grid.begin(), far_grid.end(), std::mt19937(5));
  check_one_triangulation(far_grid, true);
}

TEST(one_triangulation_on_cocircular_sets) {
  for (int n = 3; n <= 40; ++n) {
    check_one_triangulation(regular_polygon(n, 1.0, {0, 0}, false), true);
    check_one_triangulation(regular_polygon(n, 2.5, {3, -1}, true), true);
  }
  check_one_triangulation(mirrored_rings(5, 4), true);
  check_one_triangulation(mirrored_rings(16, 12), true);
  check_one_triangulation(lattice_circles({5, 25, 65}, {0, 0}), true);
  check_one_triangulation(lattice_circles({65, 85, 125}, {0.5, 1000}), true);
  for (unsigned seed = 0; seed < 10; ++seed) check_one_triangulation(lattice_subset(12, 10, 0.5, seed), true);
  check_one_triangulation(lattice_subset(150, 130, 0.3, 11), false);
}

TEST(one_triangulation_on_random_points) {
  for (std::size_t n = 3; n <= 30; ++n)
    for (unsigned seed = 0; seed < 5; ++seed) check_one_triangulation(uniform(n, seed * 100 + n), true);
  check_one_triangulation(uniform(20000, 31), false);
  check_one_triangulation(gaussian(20000, 32), false);
  check_one_triangulation(shuffled_grid(141, 142, 33), false);
}

TEST(sweepline_small_sizes) {
  for (std::size_t n = 3; n <= 40; ++n)
    for (unsigned seed = 0; seed < 20; ++seed) check_point_set(uniform(n, seed * 100 + n), DelaunayAlgorithm::Sweepline);
}
