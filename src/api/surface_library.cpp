// deltri::api::mesh_surface: facets in 3-D as arrays, checked as the facet file reader checks them
// (io/facet_file.h; the file:line replaced by the item), through the surface pipeline
// (pipeline/surface_pipeline.h) to arrays with the items and order of the .node, .ele and .edge writers
// (surface/surface_files.h).
#include <cmath>
#include <string>

#include "api/library_support.h"
#include "pipeline/surface_pipeline.h"

namespace deltri {
namespace {

[[noreturn]] void fail(const std::string& message) { throw api::Error(DELTRI_INPUT_ERROR, message); }

std::string count(std::size_t n) { return std::to_string(n); }

void read_points(const api::Facets& in, FacetInput& out) {
  if (in.points.size() % 3 != 0) fail("points holds " + count(in.points.size()) + " values, not three per point");
  const std::size_t n = in.points.size() / 3;
  if (n < 3) fail("facets need at least 3 points, the input has " + count(n));
  if (n > 0xFFFFFFF0u) fail("too many points: " + count(n));
  const double* xyz = in.points.data();
  for (std::size_t k = 0; k < n; ++k, xyz += 3) {
    const Point3 p{xyz[0], xyz[1], xyz[2]};
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      fail("point " + count(k + static_cast<std::size_t>(out.first_index)) + ": a coordinate is not a finite number");
    out.points.push_back(p);
  }
  if (!in.point_markers.empty() && in.point_markers.size() != n)
    fail("point_markers holds " + count(in.point_markers.size()) + " values for " + count(n) + " points");
  out.has_markers = !in.point_markers.empty();
  out.markers = in.point_markers;
}

std::vector<std::uint32_t> read_polygon(const std::vector<int>& polygon, const FacetInput& out, long long facet,
                                        std::size_t number) {
  if (polygon.empty()) fail("facet " + std::to_string(facet) + ": polygon " + count(number) + " has no corners");
  const long long first = out.first_index;
  const long long last = first + static_cast<long long>(out.points.size()) - 1;
  std::vector<std::uint32_t> corners;
  for (const int v : polygon) {
    if (v < first || v > last) fail(corner_not_a_point(facet, v, first, last));
    corners.push_back(static_cast<std::uint32_t>(v - first));
  }
  return corners;
}

void read_facet(const api::Facet& in, FacetInput& out) {
  const long long number = out.first_index + static_cast<long long>(out.facets.size());
  if (in.polygons.empty()) fail("facet " + std::to_string(number) + ": it has no polygons");
  if (in.holes.size() % 3 != 0)
    fail("facet " + std::to_string(number) + ": holes holds " + count(in.holes.size()) + " values, not three per hole");
  FacetInput::Facet f;
  f.marker = in.marker;
  for (std::size_t p = 0; p < in.polygons.size(); ++p)
    f.polygons.push_back(read_polygon(in.polygons[p], out, number, p + static_cast<std::size_t>(out.first_index)));
  for (std::size_t h = 0; h + 2 < in.holes.size(); h += 3) f.holes.push_back({in.holes[h], in.holes[h + 1], in.holes[h + 2]});
  out.facets.push_back(std::move(f));
}

FacetInput facet_input_of(const api::Facets& in, int first_index) {
  FacetInput out;
  out.source_name = "input";
  out.first_index = first_index;
  read_points(in, out);
  if (in.facets.empty()) fail("the input has no facets");
  for (const api::Facet& f : in.facets) read_facet(f, out);
  return out;
}

// The .node, .ele and .edge items (surface/surface_files.cpp), numbered from first_index.
api::Surface surface_arrays(const SurfaceMesh& m, const Options& sw, int first_index) {
  api::Surface s;
  s.point_count = static_cast<int>(m.points.size());
  for (const Point3& p : m.points) s.points.insert(s.points.end(), {p.x, p.y, p.z});
  if (m.has_markers && !sw.no_markers) s.point_markers = m.markers;
  s.triangle_count = static_cast<int>(m.triangle_count());
  for (const std::array<std::uint32_t, 3>& corners : m.triangles)
    for (const std::uint32_t v : corners) s.triangles.push_back(static_cast<int>(v) + first_index);
  for (const std::uint32_t f : m.triangle_facet) {
    s.triangle_attributes.push_back(m.facet_marker[f]);
    s.triangle_facets.push_back(static_cast<int>(f) + first_index);
  }
  s.edge_count = static_cast<int>(m.subsegments.size());
  for (std::size_t e = 0; e < m.subsegments.size(); ++e) {
    s.edges.push_back(static_cast<int>(m.subsegments[e].a) + first_index);
    s.edges.push_back(static_cast<int>(m.subsegments[e].b) + first_index);
    if (!sw.no_markers) s.edge_markers.push_back(m.subsegment_marker(e));
  }
  return s;
}

api::Surface run(const api::Facets& facets, const std::string& switches) {
  const Options sw = parse_library_switches(switches, false);
  const int first_index = sw.zero_based ? 0 : 1;
  const FacetInput input = facet_input_of(facets, first_index);
  const SurfaceResult result = run_surface_pipeline(input, sw);
  if (result.check_failed() && sw.check)
    throw api::Error(DELTRI_CHECK_FAILED, "C: the surface mesh is not consistent: " + result.check->summary());
  if (result.check_failed())
    throw api::Error(DELTRI_CHECK_FAILED, "the surface mesh is not consistent (" + result.check->one_line() + ")");
  api::Surface s = surface_arrays(result.mesh, sw, first_index);
  for (const auto& [point, earlier] : result.merged)
    s.merged_points.insert(s.merged_points.end(), {static_cast<int>(point) + first_index, static_cast<int>(earlier) + first_index});
  for (const std::uint32_t f : result.report.emptied_facets) s.emptied_facets.push_back(static_cast<int>(f) + first_index);
  s.budget_reached = result.report.budget_reached;
  s.rounds_exhausted = !result.report.converged && !result.report.budget_reached;
  s.triangles_below_angle = static_cast<int>(result.below_angle);
  s.triangles_above_area = static_cast<int>(result.above_area);
  s.warnings = surface_warnings(result, sw, first_index);
  return s;
}

}  // namespace

api::Surface api::mesh_surface(const Facets& facets, const std::string& switches) {
  try {
    return run(facets, switches);
  } catch (...) {
    rethrow_as_library_error();
  }
}

}  // namespace deltri
