// Inputs that once broke refinement, judged by independent facts about the result.
#include <cmath>
#include <numbers>
#include <vector>

#include "cdt/holes_and_regions.h"
#include "cdt/insert_segments.h"
#include "harness/check.h"
#include "harness/id_literals.h"
#include "refine/refine.h"
#include "refine_fixtures.h"

using namespace deltri;
using namespace refine_test;

namespace {

// The constrained Delaunay triangulation of a segment-bounded PSLG, exterior removed.
Mesh pslg_mesh(const std::vector<Point>& points, const std::vector<std::pair<int, int>>& segments) {
  Mesh m = triangulated(points);
  Predicates pred;
  std::vector<Pslg::Segment> segs;
  for (auto [a, b] : segments) segs.push_back({static_cast<std::uint32_t>(a), static_cast<std::uint32_t>(b), 0});
  insert_segments(m, pred, segs, {});
  carve_holes(m, pred, {}, false);
  return m;
}

void check_valid(const Mesh& m) {
  const Facts f = facts_of(m);
  CHECK(f.all_ccw);
  CHECK(f.links_ok);
  CHECK(f.subsegments_symmetric);
  CHECK(f.boundary_protected);
  CHECK_EQ(f.non_delaunay_edges, std::size_t{0});
}

double distance(const Point& a, const Point& b) { return std::hypot(a.x - b.x, a.y - b.y); }

}  // namespace

// CGAL's clusters.poly: eight segments fan out of vertex 1 inside a box. SPLITPERMITTED used to
// decline splits of the long cluster subsegments and leave a 24-degree triangle 250 units from
// the apex. Now every triangle under 30 degrees must sit at the apex or have its shortest edge
// joining points equidistant from it (the isosceles triangles the shells make), as in Triangle.
TEST(cluster_far_from_apex_meets_the_bound) {
  const std::vector<Point> pts{{812.183, 152.284},   {-20.3046, 30.4569}, {662.437, 365.482},
                               {824.873, 53.2995},   {819.797, -119.289}, {-116.751, -441.624},
                               {-279.188, -418.782}, {-784.264, 109.137}, {-710.66, 225.888},
                               {-1186.55, -643.401}, {1227.16, -643.401}, {1227.16, 567.259},
                               {-1186.55, 567.259}};
  Mesh m = pslg_mesh(pts, {{0, 1}, {8, 1}, {1, 2}, {0, 1}, {3, 1}, {12, 9}, {11, 10}, {4, 1},
                           {5, 1}, {6, 1}, {12, 11}, {9, 10}});
  Predicates pred;
  refine_mesh(m, pred, quality(30));
  check_valid(m);
  const Point& apex = pts[1];
  for (TriangleId t : skinny_triangles(m, 30.0)) {
    bool at_apex = false;
    for (unsigned i = 0; i < 3; ++i) at_apex = at_apex || m.corner[edge_of(t, i)] == 1;
    double shortest = HUGE_VAL;
    Point a, b;
    for (unsigned i = 0; i < 3; ++i) {
      const Point& p = m.point(m.corner[edge_of(t, i)]);
      const Point& q = m.point(m.corner[3 * t + (i + 1) % 3]);
      if (distance(p, q) < shortest) shortest = distance(p, q), a = p, b = q;
    }
    const bool isosceles = std::fabs(distance(a, apex) - distance(b, apex)) <= 0.01 * distance(a, apex);
    CHECK(at_apex || isosceles);
  }
}

// A 1-degree wedge, from debug2.poly's 0.1-degree spikes (10,000 vertices, 665,345 triangles at
// -q30 before, against 537,213 from Triangle 1.6). Split points on the two sides fell at unrelated
// distances from the apex, encroached on each other and cut the subsegments down to the wedge's
// width: 138 triangles here. Split points across the wedge must now pair up at equal distances
// from the apex, which leaves the skinny triangles between them exempt and the subsegments long.
TEST(thin_wedge_split_points_pair_up) {
  const double a = 1.0 * std::numbers::pi / 180.0;
  Mesh m = pslg_mesh({{0, 0}, {1, 0}, {0.83 * std::cos(a), 0.83 * std::sin(a)}}, {{0, 1}, {1, 2}, {2, 0}});
  Predicates pred;
  refine_mesh(m, pred, quality(30));
  check_valid(m);
  std::vector<double> on_x, on_other;  // distances from the apex of the split points of 0-1, 0-2
  for (VertexId v{3}; v < m.vertex_count(); ++v) {
    if (m.kind[v] != VertexKind::Segment) continue;
    const Point& p = m.point(v);
    if (p.y == 0.0) on_x.push_back(distance(p, {0, 0}));
    else if (std::fabs(std::atan2(p.y, p.x) - a) < 1e-9) on_other.push_back(distance(p, {0, 0}));
  }
  CHECK(on_other.size() >= 3);
  std::size_t unpaired = 0;
  for (double r2 : on_other) {
    bool paired = false;
    for (double r1 : on_x) paired = paired || std::fabs(r1 - r2) <= 1e-12 * r2;
    unpaired += paired ? 0 : 1;
  }
  // The last split before the far corner may fall between its neighbours' distances.
  CHECK(unpaired <= 1);
  CHECK(m.live_triangles() < 50);
  for (TriangleId t : skinny_triangles(m, 30.0)) CHECK(min_angle_deg(m, t) >= 1.0 - 1e-9);
}

// A strip 256 long and 1 wide. The guard's local feature estimate (distance-extended from the
// corners) read 100 in the middle, and its floor refused ordinary insertions there: 17 triangles
// with a 0.45-degree angle came out.
TEST(long_strip_is_not_stopped_by_the_guard) {
  Mesh m = pslg_mesh({{0, 0}, {256, 0}, {256, 1}, {0, 1}}, {{0, 1}, {1, 2}, {2, 3}, {3, 0}});
  Predicates pred;
  const RefineReport r = refine_mesh(m, pred, quality(30));
  check_valid(m);
  CHECK_EQ(r.guard_refusals, std::uint64_t{0});
  CHECK(facts_of(m).min_angle >= 30.0 - 1e-9);
  CHECK_NEAR(facts_of(m).total_area, 256.0, 1e-9);
}

// From greenland.node: vertex 2 lies 2e-15 inside the hull edge 0-1, closer than an ulp. Rounded
// split points of that edge landed beyond it, making a clockwise triangle (and on the full input
// the refinement went on to flat triangles whose NaN circumcentres crashed the walk). The command
// line takes such a vertex into the hull chain first (absorb_near_hull_vertices); here refinement
// meets it as it is, and goes down to the bottom scale around it (1,182 triangles, four left
// under the bound).
TEST(vertex_flush_with_a_hull_edge_keeps_the_mesh_valid) {
  Mesh m = triangulated({{105, 39.5}, {106.5, 40}, {105.9270595086, 39.8090198362}, {105.5, 41}, {104.8, 40.6}});
  mark_boundary(m);
  Predicates pred;
  refine_mesh(m, pred, quality(30));
  const Facts f = facts_of(m);
  CHECK(f.all_ccw);
  CHECK(f.links_ok);
  CHECK(f.subsegments_symmetric);
  CHECK(f.boundary_protected);
  CHECK(f.triangles < 5000);  // the precision floor stops it at the ulp scale
}
