// Facets in 3-D: plane frames, and meshes that agree on shared segments (checked here against
// facts computed from the input, not against the mesher's own bookkeeping).
#include <cmath>
#include <map>
#include <set>

#include "harness/check.h"
#include "io/facet_file.h"
#include "util/errors.h"
#include "surface/check_surface.h"
#include "surface/surface_mesher.h"

using namespace deltri;

namespace {

// Three facets meeting at the segment from (0,0,0) to (0,0,1): two in the plane y = 0 on either
// side, one in x = 0 with a lone vertex 0.05 from the segment, which forces splits there.
FacetInput tee() {
  FacetInput in;
  in.source_name = "tee";
  in.points = {{0, 0, 0}, {2, 0, 0}, {2, 0, 1}, {0, 0, 1}, {-0.5, 0, 0}, {-0.5, 0, 1}, {0, 1, 0}, {0, 1, 1}, {0, 0.05, 0.3}};
  in.facets.resize(3);
  in.facets[0].polygons = {{0, 1, 2, 3}};
  in.facets[1].polygons = {{0, 4, 5, 3}};
  in.facets[2].polygons = {{0, 6, 7, 3}, {8}};
  for (int f = 0; f < 3; ++f) in.facets[f].marker = f + 1;
  return in;
}

FacetMeshOptions quality30() {
  FacetMeshOptions opt;
  opt.refine = true;
  opt.refinement.angle = deltri::AngleBound(30.0);
  return opt;
}

double area(const SurfaceMesh& m, std::size_t t) {
  const Point3& a = m.points[m.triangles[t][0]];
  return 0.5 * norm(cross(m.points[m.triangles[t][1]] - a, m.points[m.triangles[t][2]] - a));
}

}  // namespace

TEST(plane_frame_is_orthonormal_and_keeps_lengths) {
  FacetInput in;
  in.source_name = "tilted";
  const double c = std::cos(0.3), s = std::sin(0.3);
  in.points = {{0, 0, 0}, {1, 0, 0}, {1, c, s}, {0, c, s}};
  in.facets.resize(1);
  in.facets[0].polygons = {{0, 1, 2, 3}};
  const FacetPlane p = fit_facet_plane(in, 0);
  CHECK_NEAR(norm(p.u), 1.0, 1e-15);
  CHECK_NEAR(norm(p.v), 1.0, 1e-15);
  CHECK_NEAR(dot(p.u, p.v), 0.0, 1e-15);
  CHECK_NEAR(std::fabs(dot(p.normal, Point3{0, -s, c})), 1.0, 1e-15);
  const Point a = p.to_plane(in.points[0]), b = p.to_plane(in.points[2]);
  CHECK_NEAR(std::hypot(b.x - a.x, b.y - a.y), std::sqrt(2.0), 1e-15);
  in.points[2].z += 0.01;
  const std::string what = [&] {
    try {
      fit_facet_plane(in, 0);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  }();
  CHECK(what.find("facet 1: not planar") != std::string::npos);
}

TEST(tee_facets_conform_along_the_shared_segment) {
  SurfaceReport report;
  const SurfaceMesh m = mesh_surface(tee(), quality30(), report);
  CHECK(report.converged);
  CHECK_EQ(report.shared_segments, 1u);
  CHECK(report.shared_splits > 0);
  CHECK(check_surface(m).ok());
  // Facet areas from the input: 2, 0.5 and 1.
  std::map<std::uint32_t, double> sum;
  for (std::size_t t = 0; t < m.triangle_count(); ++t) sum[m.triangle_facet[t]] += area(m, t);
  CHECK_NEAR(sum[0], 2.0, 1e-12);
  CHECK_NEAR(sum[1], 0.5, 1e-12);
  CHECK_NEAR(sum[2], 1.0, 1e-12);
  // The vertices on the shared segment (x = y = 0) used by each facet: the same set in all three.
  std::map<std::uint32_t, std::set<std::uint32_t>> on_segment;
  for (std::size_t t = 0; t < m.triangle_count(); ++t)
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t v = m.triangles[t][i];
      if (m.points[v].x == 0.0 && m.points[v].y == 0.0) on_segment[m.triangle_facet[t]].insert(v);
    }
  CHECK(on_segment[0].size() > 2);
  CHECK(on_segment[0] == on_segment[1]);
  CHECK(on_segment[0] == on_segment[2]);
  // Every edge along the segment is in three triangles (one per facet).
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> uses;
  for (std::size_t t = 0; t < m.triangle_count(); ++t)
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t a = m.triangles[t][i], b = m.triangles[t][(i + 1) % 3];
      if (on_segment[0].count(a) && on_segment[0].count(b)) ++uses[{std::min(a, b), std::max(a, b)}];
    }
  CHECK_EQ(uses.size(), on_segment[0].size() - 1);
  for (const auto& [edge, n] : uses) CHECK_EQ(n, 3);
}

TEST(round_cap_guard_still_conforms) {
  SurfaceReport report;
  const SurfaceMesh m = mesh_surface(tee(), quality30(), report, 1);
  CHECK(!report.converged);
  CHECK(check_surface(m).ok());
  double total = 0.0;
  for (std::size_t t = 0; t < m.triangle_count(); ++t) total += area(m, t);
  CHECK_NEAR(total, 3.5, 1e-12);
}

// A facet whose cut was not taken (another facet's split or a segment's end within 1e-10 stood in
// for it) keeps a vertex of its own on the segment. On the pyNastran gear at -q30a20 the splits
// near one small corner run down to that spacing within 100 rounds; the mesher then declared the
// surface converged with such facets, and 203 subsegments were no edge of a facet holding them.
TEST(a_cut_not_taken_meshes_its_facet_again) {
  const FacetInput in = read_facet_file(DELTRI_SOURCE_DIR "/tests/surface/inputs/pynastran_gear.smesh");
  FacetMeshOptions opt = quality30();
  opt.refinement.size.max_area = 20.0;
  SurfaceReport report;
  const SurfaceMesh m = mesh_surface(in, opt, report, 100);
  CHECK(check_surface(m).ok());
}

TEST(two_threads_give_the_same_surface) {
  // A 2 x 1 x 1 box made of unit squares: 10 facets, every segment shared by two.
  FacetInput in;
  in.source_name = "box";
  for (int z = 0; z <= 1; ++z)
    for (int y = 0; y <= 1; ++y)
      for (int x = 0; x <= 2; ++x) in.points.push_back({double(x), double(y), double(z)});
  const auto id = [](int x, int y, int z) { return static_cast<std::uint32_t>(x + 3 * y + 6 * z); };
  const auto square = [&](std::vector<std::uint32_t> loop) {
    FacetInput::Facet f;
    f.polygons = {std::move(loop)};
    f.marker = static_cast<int>(in.facets.size()) + 1;
    in.facets.push_back(f);
  };
  for (int x = 0; x < 2; ++x) {
    square({id(x, 0, 0), id(x + 1, 0, 0), id(x + 1, 1, 0), id(x, 1, 0)});
    square({id(x, 0, 1), id(x + 1, 0, 1), id(x + 1, 1, 1), id(x, 1, 1)});
    square({id(x, 0, 0), id(x + 1, 0, 0), id(x + 1, 0, 1), id(x, 0, 1)});
    square({id(x, 1, 0), id(x + 1, 1, 0), id(x + 1, 1, 1), id(x, 1, 1)});
  }
  square({id(0, 0, 0), id(0, 1, 0), id(0, 1, 1), id(0, 0, 1)});
  square({id(2, 0, 0), id(2, 1, 0), id(2, 1, 1), id(2, 0, 1)});
  FacetMeshOptions one = quality30();
  one.refinement.size.max_area = 0.003;
  FacetMeshOptions two = one;
  two.threads = 2;
  SurfaceReport r1, r2;
  const SurfaceMesh a = mesh_surface(in, one, r1);
  const SurfaceMesh b = mesh_surface(in, two, r2);
  CHECK(check_surface(a).ok());
  CHECK(a.triangle_count() > 1000);
  CHECK(a.points == b.points);
  CHECK(a.triangles == b.triangles);
  CHECK_EQ(r1.rounds, r2.rounds);
}

namespace {

// A unit cube whose top facet names copies (points 8 to 11) of its corners 4 to 7.
FacetInput cube_with_copied_top() {
  FacetInput in;
  in.source_name = "copied_top";
  for (double z : {0.0, 1.0})
    for (double y : {0.0, 1.0})
      for (double x : {0.0, 1.0}) in.points.push_back({x, y, z});
  for (std::uint32_t v = 4; v < 8; ++v) in.points.push_back(in.points[v]);
  in.facets.resize(6);
  in.facets[0].polygons = {{0, 2, 3, 1}};
  in.facets[1].polygons = {{8, 9, 11, 10}};
  in.facets[2].polygons = {{0, 1, 5, 4}};
  in.facets[3].polygons = {{1, 3, 7, 5}};
  in.facets[4].polygons = {{3, 2, 6, 7}};
  in.facets[5].polygons = {{2, 0, 4, 6}};
  return in;
}

}  // namespace

// The mesher alone (the pipeline merges copies first) leaves the top's border apart from the
// sides': -C must say the surface is cracked, where it used to pass.
TEST(check_finds_a_crack_along_copied_points) {
  SurfaceReport report;
  const SurfaceMesh m = mesh_surface(cube_with_copied_top(), FacetMeshOptions{}, report);
  CHECK(m.triangle_count() == 12);
  const SurfaceCheck c = check_surface(m);
  CHECK(c.faults == 4);
  CHECK(c.summary().find("the surface is cracked there") != std::string::npos);
}

// A facet scaled to 1e155 or 1e-100 spans a plane (its squared lengths used to overflow or
// underflow into "collinear"), and its frame keeps lengths.
TEST(plane_frame_at_extreme_scales) {
  for (double s : {1e-100, 1e100, 1e155, 1e300}) {
    FacetInput in;
    in.source_name = "scaled";
    in.points = {{0, 0, s}, {s, 0, s}, {s, s, s}, {0, s, s}};
    in.facets.resize(1);
    in.facets[0].polygons = {{0, 1, 2, 3}};
    const FacetPlane p = fit_facet_plane(in, 0);
    CHECK(std::abs(std::abs(p.normal.z) - 1.0) < 1e-15);
    const Point a = p.to_plane(in.points[0]), b = p.to_plane(in.points[2]);
    CHECK(std::abs(std::hypot(b.x - a.x, b.y - a.y) / (s * std::sqrt(2.0)) - 1.0) < 1e-14);
  }
}

// A hole point off its facet's plane is refused at its own line, naming the distance.
TEST(hole_point_off_the_plane_is_refused) {
  FacetInput in = cube_with_copied_top();
  in.facets[1].holes = {{0.5, 0.5, 6.0}};
  in.facets[1].hole_lines = {42};
  std::string what;
  try {
    fit_facet_plane(in, 1);
  } catch (const InputError& e) {
    what = e.what();
  }
  CHECK(what.find(":42: facet 2: hole 1 lies 5 from the facet's plane") != std::string::npos);
}

// A corner of facet 2 at the midpoint of facet 1's edge 0-1, which facet 1 has no corner at: refused
// before meshing at facet 2's line, naming both facets and the point. With the point a corner of
// facet 1 too (its polygon 0, 4, 1, 2, 3), the same geometry is a complex and meshes; the mesher
// alone, -a splitting the edges, puts no two vertices at one point (check_surface's crack test).
TEST(corner_inside_another_facets_segment_is_refused) {
  FacetInput in;
  in.source_name = "standing";
  in.points = {{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}, {1, 0, 0}, {1, -1, 1}, {1, 1, 1}};
  in.facets.resize(2);
  in.facets[0].polygons = {{0, 1, 2, 3}};
  in.facets[1].polygons = {{4, 5, 6}};
  in.facets[1].line = 17;
  FacetMeshOptions opt = quality30();
  opt.refinement.size.max_area = 0.1;
  std::string what;
  try {
    SurfaceReport report;
    mesh_surface(in, opt, report);
  } catch (const InputError& e) {
    what = e.what();
  }
  CHECK(what.find("standing:17: facet 2: point 5 lies inside segment 1-2, which facet 1 holds without it") !=
        std::string::npos);
  in.facets[0].polygons = {{0, 4, 1, 2, 3}};
  SurfaceReport report;
  const SurfaceMesh m = mesh_surface(in, opt, report);
  CHECK(m.triangle_count() > 20);
  CHECK(check_surface(m).faults == 0);
}

// A cube of size 2^-492 (what the pipeline meshes for a unit cube beside a point at 1e148): no
// triangle has zero area, which the check decided by the length of a cross product that
// underflowed to 0 (12 faults); now by exact collinearity.
TEST(check_keeps_tiny_triangles_apart_from_zero_area_ones) {
  FacetInput in = cube_with_copied_top();
  in.facets[1].polygons = {{4, 5, 7, 6}};
  in.points.resize(8);
  for (Point3& p : in.points) p = {std::ldexp(p.x, -492), std::ldexp(p.y, -492), std::ldexp(p.z, -492)};
  SurfaceReport report;
  SurfaceMesh m = mesh_surface(in, FacetMeshOptions{}, report);
  CHECK(m.triangle_count() == 12);
  CHECK(check_surface(m).faults == 0);
  m.points[m.triangles[0][2]] = m.points[m.triangles[0][0]] + 0.5 * (m.points[m.triangles[0][1]] - m.points[m.triangles[0][0]]);
  CHECK(check_surface(m).summary().find("triangle 1 has zero area in space") != std::string::npos);
}
