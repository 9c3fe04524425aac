#include "pipeline/surface_pipeline.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

#include "pipeline/pipeline.h"

namespace deltri {
namespace {

// A bare -a has no per-triangle bounds to use on facets, so those are switched off.
FacetMeshOptions facet_options(const Options& sw) {
  FacetMeshOptions o;
  o.algorithm = sw.algorithm;
  o.threads = threads_to_use(sw);
  o.refine = sw.quality || sw.fixed_area || sw.user_test || sw.conforming_delaunay;
  o.refinement = refine_options(sw, criteria_of(sw, false));
  o.refinement.size.triangle_bounds = false;
  o.steiner_total = sw.max_steiner;
  return o;
}

// Inputs whose largest coordinate lies within 2^+-kScaleFree are meshed as given; others are
// scaled by a power of two into [1, 2) first (and the mesh back), exactly: the 2-D pipeline and
// the plane frames then see coordinates of ordinary size, and the mesh does not depend on the
// input's scale.
constexpr int kScaleFree = 64;

int scale_exponent(const FacetInput& input) {
  double largest = 0.0;
  const auto see = [&](const Point3& p) { largest = std::max({largest, std::abs(p.x), std::abs(p.y), std::abs(p.z)}); };
  for (const Point3& p : input.points) see(p);
  for (const FacetInput::Facet& f : input.facets)
    for (const Point3& h : f.holes) see(h);
  if (!(largest > 0.0) || !std::isfinite(largest)) return 0;
  const int e = std::ilogb(largest);
  return std::abs(e) <= kScaleFree ? 0 : -e;
}

Point3 scaled(const Point3& p, int e) { return {std::ldexp(p.x, e), std::ldexp(p.y, e), std::ldexp(p.z, e)}; }

// Points with the coordinates of an earlier point are that point: facets naming either then share
// their segments (two copies would leave a crack along each, every facet's border its own). The
// copies stay in the output's point list, unused, as the 2-D pipeline keeps duplicate vertices.
std::vector<std::pair<std::uint32_t, std::uint32_t>> merge_duplicates(FacetInput& input) {
  std::map<std::tuple<double, double, double>, std::uint32_t> first;
  std::vector<std::uint32_t> same(input.points.size());
  std::vector<std::pair<std::uint32_t, std::uint32_t>> merged;
  for (std::uint32_t v = 0; v < input.points.size(); ++v) {
    const Point3& p = input.points[v];
    // +0 and -0 are one coordinate.
    const auto [it, added] = first.emplace(std::tuple{p.x + 0.0, p.y + 0.0, p.z + 0.0}, v);
    same[v] = it->second;
    if (!added) merged.emplace_back(v, it->second);
  }
  if (merged.empty()) return merged;
  for (FacetInput::Facet& f : input.facets)
    for (std::vector<std::uint32_t>& polygon : f.polygons) {
      for (std::uint32_t& v : polygon) v = same[v];
      // A loop whose consecutive corners became one point keeps one of them.
      if (polygon.size() >= 3) {
        polygon.erase(std::unique(polygon.begin(), polygon.end()), polygon.end());
        while (polygon.size() > 1 && polygon.front() == polygon.back()) polygon.pop_back();
      }
    }
  return merged;
}

// The triangles that miss the bounds, counted in the coordinates the facets were meshed in.
void count_misses(const SurfaceMesh& m, const Options& sw, const AngleBound& angle, double max_area, SurfaceResult& result) {
  for (std::size_t t = 0; t < m.triangle_count(); ++t) {
    const std::array<std::uint32_t, 3>& v = m.triangles[t];
    const Point3 p[3] = {m.points[v[0]], m.points[v[1]], m.points[v[2]]};
    result.below_angle += below_angle_bound(surface_smallest_angle(p[0], p[1], p[2]), angle);
    result.above_area += sw.fixed_area && 0.5 * norm(cross(p[1] - p[0], p[2] - p[0])) > max_area;
  }
}

std::string numbered(std::uint32_t v, int first) { return std::to_string(static_cast<long long>(v) + first); }

std::string plural(std::size_t n, const char* one, const char* many) { return std::to_string(n) + " " + (n == 1 ? one : many); }

// "1 into 2, 3 into 2, ..." (at most 8 named).
template <class Name>
std::string first_eight(std::size_t n, Name name) {
  std::string which;
  for (std::size_t i = 0; i < n && i < 8; ++i) which += std::string(i ? ", " : "") + name(i);
  return which + (n > 8 ? ", ..." : "");
}

}  // namespace

std::vector<std::string> surface_warnings(const SurfaceResult& result, const Options& sw, int first) {
  std::vector<std::string> w;
  const SurfaceReport& report = result.report;
  if (!result.merged.empty())
    w.push_back(plural(result.merged.size(), "point repeats", "points repeat") +
                " the coordinates of an earlier point, merged into it: " +
                first_eight(result.merged.size(), [&](std::size_t i) {
                  return numbered(result.merged[i].first, first) + " into " + numbered(result.merged[i].second, first);
                }));
  if (!report.emptied_facets.empty())
    w.push_back(plural(report.emptied_facets.size(), "facet", "facets") +
                " left with no triangle: a hole point lies in the region of its outer loop, which it carves away whole "
                "when no inner loop encloses it (facet " +
                first_eight(report.emptied_facets.size(), [&](std::size_t i) { return numbered(report.emptied_facets[i], first); }) +
                "); the surface is open there");
  const std::string misses = std::to_string(result.below_angle) + " of " + std::to_string(result.mesh.triangle_count()) +
                             " triangles below the -q angle, " + std::to_string(result.above_area) + " above the -a area";
  if (report.budget_reached)
    w.push_back("the surface run spent its budget of " + std::to_string(report.steiner_budget) + " Steiner points (" +
                (sw.max_steiner >= 0 && report.steiner_budget == sw.max_steiner ? "-S" : "the termination guard's") +
                ", shared by every facet and round): " + misses);
  else if (!report.converged)
    w.push_back("the facets did not agree on their shared segments within " + std::to_string(kMaxSurfaceRounds) +
                " rounds; meshed again with no Steiner points on segments: " + misses);
  return w;
}

double surface_smallest_angle(const Point3& a, const Point3& b, const Point3& c) {
  const Point3 p[3] = {a, b, c};
  double best = 180.0;
  for (int i = 0; i < 3; ++i) {
    const Point3 u = p[(i + 1) % 3] - p[i], w = p[(i + 2) % 3] - p[i];
    best = std::min(best, std::atan2(norm(cross(u, w)), dot(u, w)) * 57.29577951308232);
  }
  return best;
}

SurfaceResult run_surface_pipeline(const FacetInput& given, const Options& sw, const SurfaceProgress& progress) {
  SurfaceResult result;
  FacetInput input = given;
  result.merged = merge_duplicates(input);
  const int e = scale_exponent(input);
  FacetMeshOptions options = facet_options(sw);
  if (e != 0) {
    for (Point3& p : input.points) p = scaled(p, e);
    for (FacetInput::Facet& f : input.facets)
      for (Point3& h : f.holes) h = scaled(h, e);
    SizeBounds& size = options.refinement.size;
    if (size.max_area > 0.0) size.max_area = std::ldexp(size.max_area, 2 * e);
    if (size.max_edge_length > 0.0) size.max_edge_length = std::ldexp(size.max_edge_length, e);
  }
  result.mesh = mesh_surface(input, options, result.report, kMaxSurfaceRounds, progress);
  result.check = check_surface(result.mesh);
  if (!result.report.converged || result.report.budget_reached)
    count_misses(result.mesh, sw, options.refinement.angle, options.refinement.size.max_area, result);
  if (e != 0) {
    // Back to the input's scale. The copies of merged points, untouched by the scaling, are the
    // input's own coordinates.
    for (Point3& p : result.mesh.points) p = scaled(p, -e);
    for (std::uint32_t v = 0; v < given.points.size(); ++v) result.mesh.points[v] = given.points[v];
  }
  return result;
}

}  // namespace deltri
