// Refinement in two halves (refine/refine_in_parts.h), judged by independent facts about the result and
// against one Terminator on the whole mesh.
#include <cmath>
#include <cstdint>
#include <cstdio>

#include "harness/check.h"
#include "harness/id_literals.h"
#include "refine/refine_in_parts.h"
#include "refine/refine.h"
#include "refine_fixtures.h"

using namespace deltri;
using namespace refine_test;

namespace {

constexpr double kLineY = 0.5;
constexpr int kLinePoints = 99;  // (0.01 k, 0.5) for k = 1..99, a segment chain across the cut

// 14,000 scattered points in the unit square (none within 0.006 of the line y = 0.5, so that the
// chain's edges are Delaunay: their diametral circles, of radius 0.005, stay empty), the corners,
// and the chain; the hull is the boundary (marker 1), the chain a segment (marker 3). Every
// triangle carries attribute 7 and area bound 0.0002.
Mesh scattered_square_with_chain() {
  std::vector<Point> pts = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (int k = 1; k <= kLinePoints; ++k) pts.push_back({0.01 * k, kLineY});
  std::uint64_t state = 12345;
  const auto next = [&] {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(state >> 11) * 0x1p-53;
  };
  while (pts.size() < 14000) {
    const Point p{next(), next()};
    if (std::fabs(p.y - kLineY) > 0.006) pts.push_back(p);
  }
  Mesh m = triangulated(pts);
  m.marker.assign(m.vertex_count(), 0);
  mark_boundary(m, 1);
  for (VertexId k{0}; k + 1 < kLinePoints; ++k) CHECK(mark_segment(m, 4 + k, 5 + k, 3));
  m.num_triangle_attributes = 1;
  m.triangle_attributes.assign(m.triangle_slots(), 7.0);
  m.area_bound.assign(m.triangle_slots(), 0.0002);
  return m;
}

// part_min: RefineOptions::part_min_triangles; 20,000 (the program's) cuts the test meshes once,
// 300 three times (8 parts).
RefineOptions bounds_with(int threads, bool in_parts = true, std::uint32_t part_min = 20000) {
  RefineOptions opt = quality(30);
  opt.size.triangle_bounds = true;
  opt.threads = threads;
  opt.in_parts = in_parts;
  opt.part_min_triangles = part_min;
  return opt;
}

// The total length of interior subsegments (the chain; the boundary has no twins).
double interior_segment_length(const Mesh& m) {
  double length = 0.0;
  for (EdgeRef e{0}; e < m.corner.size(); ++e) {
    if (m.corner[e] == kNone || !m.subseg.has(e) || m.link[e] == kNone || m.link[e] < e) continue;
    const Point& a = m.point(m.org(e));
    const Point& b = m.point(m.dest(e));
    CHECK_EQ(a.y, kLineY);
    CHECK_EQ(b.y, kLineY);
    length += std::fabs(b.x - a.x);
  }
  return length;
}

double length_of(const Mesh& m, EdgeRef e) {
  const Point& a = m.point(m.org(e));
  const Point& b = m.point(m.dest(e));
  return std::hypot(b.x - a.x, b.y - a.y);
}

std::uint32_t vertices_in_triangles(const Mesh& m) {
  std::vector<char> used(m.vertex_count(), 0);
  for (EdgeRef e{0}; e < m.corner.size(); ++e)
    if (m.corner[e] != kNone) used[m.corner[e]] = 1;
  std::uint32_t n = 0;
  for (char u : used) n += u;
  return n;
}

}  // namespace

TEST(parts_apply_only_where_they_cannot_disagree) {
  const Mesh m = scattered_square_with_chain();
  CHECK_EQ(part_depth(m, bounds_with(2)), 1);  // 28,000 triangles: 20,000 or more, under 160,000
  CHECK_EQ(part_depth(m, bounds_with(2, true, 300)), 3);  // 19,200 or more, under 153,600
  CHECK(parts_apply(m, bounds_with(2)));
  CHECK(parts_apply(m, bounds_with(1)));  // the thread count does not decide
  CHECK(!parts_apply(m, bounds_with(2, false)));
  RefineOptions opt = bounds_with(2);
  opt.max_steiner = 1000;
  CHECK(!parts_apply(m, opt));
  opt = bounds_with(2);
  opt.no_steiner_on_segments = 1;
  CHECK(!parts_apply(m, opt));
  opt = bounds_with(2);
  opt.conforming_delaunay = true;
  CHECK(!parts_apply(m, opt));
  opt = bounds_with(2);
  opt.angle = AngleBound(40);  // can cascade (termination_guard.h)
  CHECK(!parts_apply(m, opt));
  CHECK(!parts_apply(unit_square(), bounds_with(2)));  // too small to pay
}

// Two parts and eight: every seam's triangles and subsegments meet the bounds too.
TEST(halves_meet_the_bounds_and_keep_what_triangles_carry) {
  for (std::uint32_t part_min : {20000u, 300u}) {
  Mesh m = scattered_square_with_chain();
  const std::uint32_t input_vertices = m.vertex_count();
  Predicates pred;
  const RefineReport r = refine_mesh(m, pred, bounds_with(2, true, part_min));
  const Facts f = facts_of(m);
  CHECK_EQ(r.parts, part_min == 300 ? 8u : 2u);
  std::printf("  %u parts: %u triangles, min angle %.4f, %llu + %llu Steiner, %llu deleted\n", r.parts, m.live_triangles(),
              f.min_angle, static_cast<unsigned long long>(r.interior_steiner),
              static_cast<unsigned long long>(r.segment_steiner), static_cast<unsigned long long>(r.vertices_deleted));
  CHECK(f.all_ccw);
  CHECK(f.links_ok);
  CHECK(f.subsegments_symmetric);
  CHECK(f.boundary_protected);
  CHECK_EQ(f.non_delaunay_edges, std::size_t{0});  // the seam too: exact incircle on every edge
  CHECK_NEAR(f.total_area, 1.0, 1e-12);
  CHECK_NEAR(f.boundary_length, 4.0, 1e-12);
  CHECK_NEAR(interior_segment_length(m), 0.98, 1e-12);  // the chain, split or not, all there
  CHECK(f.min_angle >= 30.0 - 1e-9);
  CHECK(f.max_area <= 0.0002);
  CHECK_EQ(r.bad_triangles_left, std::uint64_t{0});
  CHECK(!r.stopped_by_guard);
  // The Steiner counts of the halves and the seam add up to the vertices there are.
  CHECK_EQ(static_cast<std::uint64_t>(vertices_in_triangles(m)),
           input_vertices + r.interior_steiner + r.segment_steiner - r.vertices_deleted);
  for (TriangleId t{0}; t < m.triangle_slots(); ++t) {
    if (!m.is_live(t)) continue;
    CHECK_EQ(m.triangle_attributes[t], 7.0);
    CHECK_EQ(m.area_bound[t], 0.0002);
  }
  for (VertexId v{input_vertices}; v < m.vertex_count(); ++v) {
    if (m.kind[v] == VertexKind::Dead) continue;
    const bool on_chain = m.point(v).y == kLineY && m.point(v).x > 0.0 && m.point(v).x < 1.0;
    const int expected = m.kind[v] == VertexKind::Segment ? (on_chain ? 3 : 1) : 0;
    CHECK_EQ(m.marker[v], expected);
  }
  }
}

// Each half is refined as it would be alone, whatever the threads' timing; and the seam costs
// only a few triangles against one Terminator on the whole mesh.
TEST(halves_are_deterministic_and_close_to_the_whole) {
  Mesh a = scattered_square_with_chain(), b = a, whole = a;
  Predicates pa, pb, pw;
  const RefineReport ra = refine_mesh(a, pa, bounds_with(2));
  refine_mesh(b, pb, bounds_with(2));
  CHECK(Snapshot(a) == Snapshot(b));
  const RefineReport rw = refine_mesh(whole, pw, bounds_with(2, false));
  const double n = a.live_triangles(), w = whole.live_triangles();
  std::printf("  halves %u triangles, whole %u\n", a.live_triangles(), whole.live_triangles());
  CHECK(ra.in_parts && !rw.in_parts);  // the halves did run, and only where asked
  CHECK(std::fabs(n - w) <= 0.01 * w);
}

// The mesh does not depend on the number of threads: one thread refines the same parts one after
// the other, more run them at once (3: one side of the first cut gets two, the other one; 8 with
// 8 parts: each its own). Two parts and eight.
TEST(halves_give_the_same_mesh_on_one_to_eight_threads) {
  for (std::uint32_t part_min : {20000u, 300u}) {
    Mesh one = scattered_square_with_chain();
    const Mesh input = one;
    Predicates p1;
    const RefineReport r1 = refine_mesh(one, p1, bounds_with(1, true, part_min));
    CHECK(r1.in_parts);
    for (int threads : {2, 3, 4, 8}) {
      Mesh other = input;
      Predicates p;
      const RefineReport r = refine_mesh(other, p, bounds_with(threads, true, part_min));
      CHECK(Snapshot(one) == Snapshot(other));
      CHECK_EQ(r.parts, r1.parts);
      CHECK_EQ(r.interior_steiner, r1.interior_steiner);
      CHECK_EQ(r.seam_steiner, r1.seam_steiner);
    }
  }
}

// Random interior edges as segments: subsegments meeting at every angle, many of them across the
// cut, so clusters, shells and the small-angle exemption all meet the seam. Whatever the seed, the
// result is a valid constrained Delaunay mesh of the same domain with the same segments.
TEST(halves_keep_random_segments_and_the_constrained_delaunay_property) {
  for (std::uint64_t seed : {1u, 2u, 3u, 4u}) {
    std::uint64_t state = seed * 0x9E3779B97F4A7C15ULL;
    const auto next = [&] {
      state = state * 6364136223846793005ULL + 1442695040888963407ULL;
      return state >> 11;
    };
    std::vector<Point> pts = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    while (pts.size() < 12000) pts.push_back({static_cast<double>(next()) * 0x1p-53, static_cast<double>(next()) * 0x1p-53});
    Mesh m = triangulated(pts);
    mark_boundary(m, 1);
    double segment_length = 0.0;
    for (int k = 0; k < 1500; ++k) {
      const EdgeRef e = static_cast<EdgeRef>(next() % m.corner.size());
      if (m.corner[e] == kNone || m.link[e] == kNone || m.subseg.has(e)) continue;
      const SubsegmentId id = static_cast<SubsegmentId>(m.subsegments.size());
      m.subsegments.push_back({m.org(e), m.dest(e), 5, id});
      m.set_subsegment(e, id);
      segment_length += length_of(m, e);
    }
    RefineOptions opt = quality(28);
    opt.threads = 2;
    if (seed >= 3) opt.part_min_triangles = 300;  // 8 parts: seams across seams
    REQUIRE(parts_apply(m, opt));
    Predicates pred;
    const RefineReport r = refine_mesh(m, pred, opt);
    const Facts f = facts_of(m);
    std::printf("  seed %llu: %u triangles, seam %llu edges, %llu bad left\n", static_cast<unsigned long long>(seed),
                m.live_triangles(), static_cast<unsigned long long>(r.seam_edges),
                static_cast<unsigned long long>(r.bad_triangles_left));
    CHECK(r.seam_edges > 0);
    CHECK(f.all_ccw);
    CHECK(f.links_ok);
    CHECK(f.subsegments_symmetric);
    CHECK(f.boundary_protected);
    CHECK_EQ(f.non_delaunay_edges, std::size_t{0});
    CHECK_NEAR(f.total_area, 1.0, 1e-12);
    CHECK_NEAR(f.boundary_length, 4.0, 1e-12);
    double after = 0.0;
    for (EdgeRef e{0}; e < m.corner.size(); ++e)
      if (m.corner[e] != kNone && m.subseg.has(e) && m.link[e] != kNone && m.link[e] > e)
        after += length_of(m, e);
    CHECK_NEAR(after, segment_length, 1e-9 * segment_length);
  }
}

