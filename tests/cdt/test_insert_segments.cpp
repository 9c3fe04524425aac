// Segment insertion: every input segment ends up as a chain of constrained edges, the mesh stays
// valid and constrained Delaunay, and each kind of input repair is counted.
#include <algorithm>
#include <random>
#include <set>

#include "cdt/holes_and_regions.h"
#include "cdt/segment_inserter.h"
#include "mesh/subsegments.h"
#include "cdt_fixture.h"
#include "harness/id_literals.h"

using namespace cdt_test;

namespace {

std::vector<Point> box(double x0, double y0, double x1, double y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

}  // namespace

TEST(cdt_square_with_diagonal) {
  for (const auto diagonal : {Pslg::Segment{0, 2, 0}, Pslg::Segment{1, 3, 0}}) {
    Built b;
    auto segs = ring(0, 4);
    segs.push_back(diagonal);
    triangulate_and_insert(b, box(0, 0, 1, 1), segs);
    CHECK(mesh_valid(b.mesh));
    CHECK(constrained_delaunay(b.mesh));
    CHECK_EQ(b.seg.subsegments, std::size_t{5});
    CHECK_EQ(live_edges_with_subsegment(b.mesh), std::size_t{5});
    for (const auto& s : segs) CHECK(collinear_chain(b.mesh, s.a, s.b));
    CHECK_NEAR(area(b.mesh), 1.0, 1e-15);
  }
}

TEST(cdt_duplicate_vertex_in_segment) {
  Built b;
  auto pts = box(0, 0, 2, 2);
  pts.push_back({2, 2});  // 4 duplicates 2
  pts.push_back({1, 1.5});
  triangulate_and_insert(b, pts, {{0, 4, 0}, {4, 2, 0}, {5, 4, 0}});
  CHECK_EQ(b.dt.duplicates.size(), std::size_t{1});
  CHECK_EQ(b.seg.duplicates_remapped, std::size_t{3});
  CHECK_EQ(b.seg.zero_length, std::size_t{1});  // 4-2 is 2-2
  CHECK(mesh_valid(b.mesh));
  CHECK(collinear_chain(b.mesh, 0, 2));
  CHECK(collinear_chain(b.mesh, 5, 2));
  for (const auto& s : b.mesh.subsegments) CHECK(s.a != 4 && s.b != 4);
}

TEST(cdt_zero_length_and_repeated) {
  Built b;
  auto segs = ring(0, 4, 0);
  segs.push_back({2_v, 2_v, 0});
  segs.push_back({1_v, 0_v, 7});  // repeats 0-1 reversed, with a marker the original lacks
  segs.push_back({0_v, 1_v, 0});
  triangulate_and_insert(b, box(0, 0, 1, 1), segs);
  CHECK_EQ(b.seg.zero_length, std::size_t{1});
  CHECK_EQ(b.seg.repeated, std::size_t{2});
  CHECK_EQ(b.seg.subsegments, std::size_t{4});
  int marked = 0;
  for (const auto& s : b.mesh.subsegments) marked += s.marker == 7 && s.segment == 0;
  CHECK_EQ(marked, 1);
  CHECK(mesh_valid(b.mesh));
}

TEST(cdt_segment_through_vertex) {
  Built b;
  auto pts = box(0, 0, 2, 1);
  pts.push_back({1, 0});    // on the bottom edge
  pts.push_back({1, 0.5});  // on the segment 0-2? no: on the segment from (0,0) to (2,1)
  triangulate_and_insert(b, pts, {{0, 1, 3}, {1, 2, 0}, {2, 3, 0}, {3, 0, 0}, {0, 2, 0}});
  CHECK_EQ(b.seg.split_at_vertices, std::size_t{2});
  CHECK_EQ(b.seg.subsegments, std::size_t{7});
  CHECK(collinear_chain(b.mesh, 0, 1));
  CHECK(collinear_chain(b.mesh, 0, 2));
  CHECK(mesh_valid(b.mesh));
  CHECK(constrained_delaunay(b.mesh));
  for (const auto& s : b.mesh.subsegments)
    if (s.segment == 0) CHECK_EQ(s.marker, 3);
}

TEST(cdt_collinear_overlap) {
  Built b;
  auto pts = box(-1, -1, 4, 1);
  for (double x : {0.0, 1.0, 2.0, 3.0}) pts.push_back({x, 0});
  // 4=(0,0) 5=(1,0) 6=(2,0) 7=(3,0): 4-6 and 5-7 overlap on 5-6.
  triangulate_and_insert(b, pts, {{4, 6, 0}, {5, 7, 2}});
  CHECK_EQ(b.seg.split_at_vertices, std::size_t{2});
  CHECK_EQ(b.seg.overlaps_merged, std::size_t{1});
  CHECK_EQ(b.seg.subsegments, std::size_t{3});
  CHECK(collinear_chain(b.mesh, 4, 6));
  CHECK(collinear_chain(b.mesh, 5, 7));
  for (const auto& s : b.mesh.subsegments) {
    const bool shared = (s.a == 5 && s.b == 6) || (s.a == 6 && s.b == 5);
    if (shared) CHECK_EQ(s.marker, 2);  // the earlier piece had marker 0
  }
  CHECK(mesh_valid(b.mesh));
  CHECK(constrained_delaunay(b.mesh));
}

TEST(cdt_crossing_segments) {
  Built b;
  auto segs = ring(0, 4);
  segs.push_back({0_v, 2_v, 0});
  segs.push_back({1_v, 3_v, 0});
  triangulate_and_insert(b, box(0, 0, 1, 1), segs);
  CHECK_EQ(b.seg.crossings, std::size_t{1});
  REQUIRE(b.mesh.vertex_count() == 5u);
  CHECK(b.mesh.kind[4] == VertexKind::Segment);
  CHECK(b.mesh.points[4] == (Point{0.5, 0.5}));
  CHECK_EQ(b.mesh.live_triangles(), 4u);
  CHECK_EQ(b.seg.subsegments, std::size_t{8});
  CHECK(collinear_chain(b.mesh, 0, 2));
  CHECK(collinear_chain(b.mesh, 1, 3));
  CHECK(mesh_valid(b.mesh));
}

TEST(cdt_nearly_parallel_crossing) {
  Built b;
  auto pts = box(-1, -1, 2, 1);
  pts.push_back({0, 0});
  pts.push_back({1, 1e-15});
  pts.push_back({0, 1e-15});
  pts.push_back({1, 0});
  triangulate_and_insert(b, pts, {{4, 5, 0}, {6, 7, 0}});
  CHECK_EQ(b.seg.crossings, std::size_t{1});
  CHECK(mesh_valid(b.mesh));
  CHECK(constrained_delaunay(b.mesh));
  CHECK(chain_of_segment(b.mesh, 0, 4, 5));
  CHECK(chain_of_segment(b.mesh, 1, 6, 7));
  CHECK_NEAR(area(b.mesh), 6.0, 1e-14);
}

TEST(cdt_long_segment_across_random_points) {
  Built b;
  auto pts = box(0, 0, 1, 1);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < 1000; ++i) pts.push_back({u(rng), u(rng)});
  pts.push_back({0.01, 0.5});
  pts.push_back({0.99, 0.51});
  triangulate_and_insert(b, pts, {{0, 2, 0}, {1004, 1005, 0}, {1, 3, 0}});
  CHECK(mesh_valid(b.mesh));
  CHECK(constrained_delaunay(b.mesh));
  CHECK(chain_of_segment(b.mesh, 0, 0, 2));
  CHECK(chain_of_segment(b.mesh, 1, 1004, 1005));
  CHECK(chain_of_segment(b.mesh, 2, 1, 3));
  CHECK_EQ(b.seg.crossings, std::size_t{3});  // each pair of the three crosses
  CHECK_NEAR(area(b.mesh), 1.0, 1e-14);
}

TEST(cdt_grid_with_cocircular_points) {
  Built b;
  std::vector<Point> pts;
  for (int y = 0; y < 20; ++y)
    for (int x = 0; x < 20; ++x) pts.push_back({double(x), double(y)});
  // (0,0)-(19,7) meets no other grid point; (0,19)-(19,0) passes through 18 of them.
  triangulate_and_insert(b, pts, {{0, 7 * 20 + 19, 0}, {19 * 20, 19, 0}, {0, 19 * 20 + 19, 0}});
  CHECK_EQ(b.seg.split_at_vertices, std::size_t{18 + 18});
  // The anti-diagonal crosses the other two, at (9.5, 9.5) and at a point that rounds off it.
  CHECK_EQ(b.seg.crossings, std::size_t{2});
  CHECK(mesh_valid(b.mesh));
  CHECK(constrained_delaunay(b.mesh));
  CHECK(chain_of_segment(b.mesh, 0, 0, 7 * 20 + 19));
  CHECK(chain_of_segment(b.mesh, 1, 19 * 20, 19));
  CHECK(collinear_chain(b.mesh, 0, 19 * 20 + 19));
  CHECK_NEAR(area(b.mesh), 361.0, 1e-12);
}

TEST(cdt_random_segment_soup) {
  for (unsigned seed = 1; seed <= 20; ++seed) {
    Built b;
    auto pts = box(0, 0, 1, 1);
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int i = 0; i < 200; ++i) pts.push_back({u(rng), u(rng)});
    std::vector<Pslg::Segment> segs;
    std::uniform_int_distribution<std::uint32_t> pick(0, 203);
    for (int i = 0; i < 40; ++i) segs.push_back({pick(rng), pick(rng), 0});
    triangulate_and_insert(b, pts, segs);
    CHECK(mesh_valid(b.mesh));
    CHECK(constrained_delaunay(b.mesh));
    CHECK(b.seg.crossings > 0);
    CHECK_EQ(b.seg.unrecovered, std::size_t{0});
    for (std::uint32_t i = 0; i < segs.size(); ++i) {
      if (segs[i].a == segs[i].b) continue;
      // A segment is a chain of its own pieces, or of pieces shared with an earlier duplicate.
      bool ok = chain_of_segment(b.mesh, i, segs[i].a, segs[i].b);
      for (std::uint32_t j = 0; j < i && !ok; ++j) {
        const bool same = (segs[j].a == segs[i].a && segs[j].b == segs[i].b) ||
                          (segs[j].a == segs[i].b && segs[j].b == segs[i].a);
        ok = same;
      }
      CHECK(ok);
    }
    CHECK_NEAR(area(b.mesh), 1.0, 1e-13);
  }
}

TEST(cdt_star_polygon) {
  Built b;
  std::vector<Point> pts;
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> r(0.3, 1.0);
  const double pi = std::acos(-1.0);
  for (int i = 0; i < 200; ++i) {
    const double a = 2 * pi * i / 200, rad = r(rng);
    pts.push_back({rad * std::cos(a), rad * std::sin(a)});
  }
  double expected = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const Point &p = pts[i], &q = pts[(i + 1) % pts.size()];
    expected += 0.5 * (p.x * q.y - q.x * p.y);
  }
  triangulate_and_insert(b, pts, ring(0, 200));
  CHECK(mesh_valid(b.mesh));
  CHECK(constrained_delaunay(b.mesh));
  for (std::uint32_t i = 0; i < 200; ++i) CHECK(collinear_chain(b.mesh, i, (i + 1) % 200));
  const HoleReport h = carve_holes(b.mesh, b.pred, {}, false);
  CHECK_EQ(h.subsegments_removed, std::size_t{0});
  CHECK(mesh_valid(b.mesh));
  CHECK_EQ(b.mesh.live_triangles(), 198u);
  CHECK_EQ(b.mesh.free_triangles.size(), std::size_t{0});
  CHECK_NEAR(area(b.mesh), expected, 1e-13);
}

TEST(cdt_repeats_at_a_hub_vertex) {
  Built b;
  std::vector<Point> pts{{0, 0}};
  const double pi = std::acos(-1.0);
  for (int i = 0; i < 30; ++i) pts.push_back({std::cos(2 * pi * i / 30), std::sin(2 * pi * i / 30)});
  std::vector<Pslg::Segment> segs;
  for (std::uint32_t i = 1; i <= 30; ++i) segs.push_back({0, i, 0});
  for (std::uint32_t i = 1; i <= 30; i += 3) segs.push_back({i, 0, 0});  // 10 repeats, reversed
  segs.push_back({0_v, 4_v, 0});
  triangulate_and_insert(b, pts, segs);
  CHECK_EQ(b.seg.repeated, std::size_t{11});
  CHECK_EQ(b.seg.subsegments, std::size_t{30});
  CHECK(mesh_valid(b.mesh));
  CHECK(constrained_delaunay(b.mesh));
}

TEST(cdt_grid_segment_soup_with_every_degeneracy) {
  // Segments between integer grid points pass through vertices, overlap collinearly and cross
  // both at grid-free exact points and at rounded ones.
  for (unsigned seed = 1; seed <= 30; ++seed) {
    Built b;
    std::vector<Point> pts;
    for (int y = 0; y < 10; ++y)
      for (int x = 0; x < 10; ++x) pts.push_back({double(x), double(y)});
    std::mt19937_64 rng(seed);
    std::uniform_int_distribution<std::uint32_t> pick(0, 99);
    std::vector<Pslg::Segment> segs;
    for (int i = 0; i < 60; ++i) segs.push_back({pick(rng), pick(rng), 0});
    triangulate_and_insert(b, pts, segs);
    CHECK(mesh_valid(b.mesh));
    CHECK(constrained_delaunay(b.mesh));
    CHECK_EQ(b.seg.unrecovered, std::size_t{0});
    const auto all = subsegment_graph(b.mesh, [](const Subsegment&) { return true; });
    for (const auto& s : segs)
      if (s.a != s.b) CHECK(connected(all, s.a, s.b));
    CHECK_NEAR(area(b.mesh), 81.0, 1e-11);
  }
}

// insert_segments looks for every segment among the edges first (read-only, on two threads when it
// may), then inserts them in input order with what it found. The mesh must be the one that
// inserting the segments one after the other gives (SegmentInserter alone), slot for slot, with one
// thread and with two: an input where most segments are edges of the Delaunay triangulation (as on
// a fine boundary) and some cross them, flipping and splitting edges found earlier, over several
// blocks of look-ups.
TEST(cdt_found_edges_give_the_mesh_of_one_segment_after_the_other) {
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Point> pts;
  for (int i = 0; i < 50000; ++i) pts.push_back({u(rng), u(rng)});
  Mesh dt;
  dt.points.assign(pts.begin(), pts.end());
  dt.kind.assign(pts.size(), VertexKind::Input);
  delaunay_triangulate(dt, DelaunayAlgorithm::DivideAndConquer, 1);
  std::set<std::pair<VertexId, VertexId>> taken;
  std::vector<Pslg::Segment> segments;
  const auto add = [&](VertexId a, VertexId b) {
    if (a == b || !taken.insert({std::min(a, b), std::max(a, b)}).second) return;
    segments.push_back({a, b, static_cast<int>(segments.size() % 5)});
  };
  for (std::uint32_t e = 0; e < dt.corner.size(); ++e)  // about half the edges, either way round
    if (dt.corner[e] != kNone && rng() % 3 == 0) add(dt.org(EdgeRef{e}), dt.dest(EdgeRef{e}));
  for (std::size_t i = segments.size() / 3; i < segments.size(); i += 97)  // chords among them
    add(VertexId{static_cast<std::uint32_t>(rng() % pts.size())}, VertexId{static_cast<std::uint32_t>(rng() % pts.size())});
  std::shuffle(segments.begin(), segments.end(), rng);
  CHECK(segments.size() > 2 * 32768);  // over two blocks of look-ups

  const auto fresh = [&](Mesh& m) {
    m.points.assign(pts.begin(), pts.end());
    m.kind.assign(pts.size(), VertexKind::Input);
    return delaunay_triangulate(m, DelaunayAlgorithm::DivideAndConquer, 1);
  };
  Mesh one_by_one;
  fresh(one_by_one);
  one_by_one.enable_subsegments();
  Predicates pred;
  SegmentInserter inserter(one_by_one, pred, true, false);
  for (std::uint32_t i = 0; i < segments.size(); ++i)
    inserter.insert(Piece{VertexId{segments[i].a}, VertexId{segments[i].b}, segments[i].marker, i});
  drop_dead_subsegments(one_by_one);
  CHECK(inserter.counts().crossings > 100);  // the chords crossed what was there

  for (int threads : {1, 2}) {
    Mesh m;
    const DelaunayReport report = fresh(m);
    Predicates p;
    insert_segments(m, p, segments, report.duplicates, true, false, threads);
    CHECK(m.corner == one_by_one.corner);
    CHECK(m.link == one_by_one.link);
    CHECK(m.subseg == one_by_one.subseg);
    CHECK_EQ(m.subsegments.size(), one_by_one.subsegments.size());
    bool same = m.subsegments.size() == one_by_one.subsegments.size();
    for (std::size_t s = 0; same && s < m.subsegments.size(); ++s) {
      const Subsegment &x = m.subsegments[s], &y = one_by_one.subsegments[s];
      same = x.a == y.a && x.b == y.b && x.marker == y.marker && x.segment == y.segment;
    }
    CHECK(same);
    CHECK(mesh_valid(m));
  }
}
