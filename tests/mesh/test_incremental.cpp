// incremental_delaunay judged by independent facts: exact orientation and empty circles, Euler's
// formula, and the triangle count 2n - 2 - h with h from a monotone-chain hull.
#include <algorithm>

#include "delaunay/incremental.h"
#include "harness/check.h"
#include "mesh_checks.h"

using namespace deltri;
using namespace meshcheck;

namespace {

using Pairs = std::vector<std::pair<VertexId, VertexId>>;

Pairs run(Mesh& m) {
  Predicates pred;
  Pairs dups;
  incremental_delaunay(m, pred, dups);
  return dups;
}

// Whether the points span no triangle: fewer than three distinct ones, or all on one line.
bool flat(const std::vector<Point>& pts) {
  Predicates pred;
  for (const Point& a : pts)
    for (const Point& b : pts) {
      if (a == b) continue;
      for (const Point& c : pts)
        if (pred.orient2d(a, b, c) != 0) return false;
      return true;
    }
  return true;
}

// Every fact a Delaunay triangulation of `pts` must satisfy.
void check_delaunay_of(const std::vector<Point>& pts) {
  Mesh m = mesh_of(pts);
  const Pairs dups = run(m);
  const std::size_t distinct = pts.size() - dups.size();
  CHECK(m.free_triangles.empty());
  CHECK_EQ(all_faults(m), 0);
  CHECK_EQ(delaunay_faults(m), 0);
  if (flat(pts)) {
    CHECK_EQ(m.live_triangles(), 0u);
    return;
  }
  CHECK_EQ(euler_characteristic(m), 1);
  CHECK_EQ(static_cast<std::size_t>(m.live_triangles()), 2 * distinct - 2 - hull_boundary_points(pts));
  std::vector<char> used(m.vertex_count(), 0);
  for (VertexId c : m.corner) used[c] = 1;
  for (VertexId v{0}; v < m.vertex_count(); ++v) CHECK_EQ(used[v] != 0, m.kind[v] == VertexKind::Input);
}

}  // namespace

TEST(incremental_random_points) {
  for (std::size_t n : {3u, 4u, 5u, 10u, 57u, 500u, 5000u})
    for (unsigned seed = 0; seed < 3; ++seed) check_delaunay_of(uniform(n, 50 + seed + 10 * n));
}

TEST(incremental_hundred_thousand_points) {
  const auto pts = uniform(100000, 51);
  Mesh m = mesh_of(pts);
  run(m);
  CHECK_EQ(all_faults(m), 0);
  CHECK_EQ(delaunay_faults(m), 0);
  CHECK_EQ(static_cast<std::size_t>(m.live_triangles()), 2 * pts.size() - 2 - hull_boundary_points(pts));
}

TEST(incremental_is_deterministic) {
  const auto pts = uniform(3000, 52);
  Mesh a = mesh_of(pts), b = mesh_of(pts);
  run(a);
  run(b);
  CHECK(a.corner == b.corner);
  CHECK(a.link == b.link);
}

TEST(incremental_grid_with_cocircular_quads) {
  std::vector<Point> pts;
  for (int i = 0; i < 40; ++i)
    for (int j = 0; j < 30; ++j) pts.push_back({i * 0.1, j * 0.1});
  std::shuffle(pts.begin(), pts.end(), std::mt19937(53));
  check_delaunay_of(pts);
  Mesh m = mesh_of(pts);
  run(m);
  CHECK_EQ(m.live_triangles(), 2u * 39u * 29u);
}

TEST(incremental_small_grids_and_lines) {
  for (int w = 1; w <= 6; ++w)
    for (int h = 1; h <= 6; ++h) {
      std::vector<Point> pts;
      for (int i = 0; i < w; ++i)
        for (int j = 0; j < h; ++j) pts.push_back({double(i), double(j)});
      Mesh m = mesh_of(pts);
      run(m);
      const bool flat = w == 1 || h == 1;
      CHECK_EQ(m.live_triangles(), flat ? 0u : 2u * (w - 1) * (h - 1));
      CHECK_EQ(all_faults(m), 0);
      CHECK_EQ(delaunay_faults(m), 0);
    }
}

TEST(incremental_all_collinear_and_too_few) {
  std::vector<Point> line;
  for (int i = 0; i < 500; ++i) line.push_back({i * 0.5, 3.0 + i * 0.25});
  std::shuffle(line.begin(), line.end(), std::mt19937(54));
  Mesh m = mesh_of(line);
  run(m);
  CHECK_EQ(m.live_triangles(), 0u);
  CHECK(m.corner.empty());
  CHECK(std::ranges::equal(m.points, line));
  for (const auto& pts : {std::vector<Point>{}, std::vector<Point>{{1, 1}},
                          std::vector<Point>{{1, 1}, {1, 1}, {2, 2}}, std::vector<Point>{{0, 0}, {1, 1}}}) {
    Mesh s = mesh_of(pts);
    run(s);
    CHECK_EQ(s.live_triangles(), 0u);
  }
  // Collinear except for the very last point.
  line.push_back({100, -50});
  check_delaunay_of(line);
}

TEST(incremental_duplicates_keep_the_lowest_id) {
  auto pts = uniform(2000, 55);
  for (int i = 0; i < 150; ++i) pts.push_back(pts[i * 5]);
  pts.push_back(pts[5]);
  pts.insert(pts.begin() + 3, pts[900]);  // a duplicate with a lower id than... itself shifted
  Mesh m = mesh_of(pts);
  const Pairs dups = run(m);
  CHECK_EQ(dups.size(), 152u);
  for (const auto& [dup, kept] : dups) {
    CHECK(dup > kept);
    CHECK(m.kind[dup] == VertexKind::Duplicate);
    CHECK(pts[dup] == pts[kept]);
    CHECK(m.kind[kept] == VertexKind::Input);
  }
  CHECK(std::is_sorted(dups.begin(), dups.end()));
  CHECK_EQ(all_faults(m), 0);
  CHECK_EQ(delaunay_faults(m), 0);
  CHECK_EQ(static_cast<std::size_t>(m.live_triangles()), 2 * 2000 - 2 - hull_boundary_points(pts));
}

TEST(incremental_ignores_other_vertex_kinds) {
  auto pts = uniform(300, 56);
  Mesh m = mesh_of(pts);
  m.kind[10] = VertexKind::Free;
  m.kind[20] = VertexKind::Dead;
  run(m);
  for (VertexId c : m.corner) CHECK(c != 10u && c != 20u);
  CHECK_EQ(delaunay_faults(m), 0);
}

TEST(incremental_huge_offset_and_tiny_scale) {
  check_delaunay_of(uniform(5000, 57, 1.0, 1e9));
  check_delaunay_of(uniform(5000, 58, 1e-9, 0.0));
  std::vector<Point> grid;
  for (int i = 0; i < 30; ++i)
    for (int j = 0; j < 30; ++j) grid.push_back({1e9 + i * 1e-7, 1e9 + j * 1e-7});
  std::shuffle(grid.begin(), grid.end(), std::mt19937(59));
  check_delaunay_of(grid);
}

TEST(incremental_points_on_a_circle) {
  std::vector<Point> pts;
  for (int i = 0; i < 1000; ++i) pts.push_back({std::cos(i * 0.0062831), std::sin(i * 0.0062831)});
  pts.push_back({0, 0});
  check_delaunay_of(pts);
}

TEST(incremental_small_lattice_subsets) {
  // Few integer points: collinear runs, cocircular quads and repeats in every combination.
  std::mt19937 rng(60);
  for (int trial = 0; trial < 400; ++trial) {
    std::vector<Point> pts(3 + rng() % 30);
    for (Point& p : pts) p = {double(rng() % 6), double(rng() % 5)};
    check_delaunay_of(pts);
  }
}
