// The C library's facets in 3-D (deltri_mesh_surface in deltri/triangle.h): struct deltri_facets's
// flat runs to the C++ API's facets, its surface to malloc'ed arrays, statuses instead of exceptions.
#include <cstdlib>
#include <cstring>

#include "api/c_support.h"

namespace deltri {
namespace {

// The lengths of consecutive runs (polygons per facet, hole points per facet): none negative, and
// together the whole list.
void check_runs(const std::vector<int>& sizes, long long total, const char* sizes_name, const char* total_name) {
  long long sum = 0;
  for (std::size_t k = 0; k < sizes.size(); ++k) {
    if (sizes[k] < 0) fail(DELTRI_INPUT_ERROR, std::string(sizes_name) + "[" + std::to_string(k) + "] is negative");
    sum += sizes[k];
  }
  if (sum != total)
    fail(DELTRI_INPUT_ERROR, std::string(sizes_name) + " adds up to " + std::to_string(sum) + ", but " + total_name +
                                 " is " + std::to_string(total));
}

api::Facets facets_of(const deltri_facets& in) {
  api::Facets f;
  f.points = input_array(in.pointlist, in.numberofpoints, 3, "pointlist", "numberofpoints");
  f.point_markers = input_array(in.pointmarkerlist, in.numberofpoints, 1, "pointmarkerlist", "numberofpoints", true);
  const auto sizes = input_array(in.polygonsizelist, in.numberofpolygons, 1, "polygonsizelist", "numberofpolygons");
  const auto per_facet = input_array(in.facetpolygonlist, in.numberoffacets, 1, "facetpolygonlist", "numberoffacets");
  const auto holes_per_facet = input_array(in.facetholelist, in.numberoffacets, 1, "facetholelist", "numberoffacets", true);
  const auto markers = input_array(in.facetmarkerlist, in.numberoffacets, 1, "facetmarkerlist", "numberoffacets", true);
  const auto holes = input_array(in.holelist, in.numberofholes, 3, "holelist", "numberofholes");
  check_runs(per_facet, in.numberofpolygons, "facetpolygonlist", "numberofpolygons");
  check_runs(holes_per_facet, holes_per_facet.empty() ? 0 : in.numberofholes, "facetholelist", "numberofholes");
  if (holes_per_facet.empty() && in.numberofholes > 0) fail(DELTRI_INPUT_ERROR, "holelist has hole points but facetholelist is NULL");
  long long corners = 0;
  for (const int s : sizes) {
    if (s < 0) fail(DELTRI_INPUT_ERROR, "polygonsizelist holds a negative size, " + std::to_string(s));
    corners += s;
  }
  const std::vector<int> corner_values = input_array(in.cornerlist, corners, 1, "cornerlist", "the sum of polygonsizelist");
  std::size_t polygon = 0, corner = 0, hole = 0;
  for (std::size_t k = 0; k < per_facet.size(); ++k) {
    api::Facet facet;
    for (int p = 0; p < per_facet[k]; ++p, ++polygon) {
      const auto begin = corner_values.begin() + static_cast<std::ptrdiff_t>(corner);
      facet.polygons.emplace_back(begin, begin + sizes[polygon]);
      corner += static_cast<std::size_t>(sizes[polygon]);
    }
    const std::size_t h = holes_per_facet.empty() ? 0 : static_cast<std::size_t>(holes_per_facet[k]);
    constexpr std::size_t kXyz = 3;  // coordinates per hole point
    facet.holes.assign(holes.begin() + static_cast<std::ptrdiff_t>(kXyz * hole),
                       holes.begin() + static_cast<std::ptrdiff_t>(kXyz * (hole + h)));
    hole += h;
    facet.marker = markers.empty() ? 0 : markers[k];
    f.facets.push_back(std::move(facet));
  }
  return f;
}

// A malloc'ed copy of `values` (NULL when empty), into `list`, freeing all of `got` if one fails.
template <class T>
void copy_out(T** list, const std::vector<T>& values, std::vector<void*>& got) {
  *list = nullptr;
  if (values.empty()) return;
  void* memory = std::malloc(values.size() * sizeof(T));
  if (memory == nullptr) {
    for (void* p : got) std::free(p);
    fail(DELTRI_MEMORY_ERROR, "out of memory for the output arrays");
  }
  std::memcpy(memory, values.data(), values.size() * sizeof(T));
  got.push_back(memory);
  *list = static_cast<T*>(memory);
}

// Fills a copy first, so that a failed allocation leaves *out untouched.
void write_surface(const api::Surface& s, deltri_surface& out) {
  deltri_surface r{};
  std::vector<void*> got;
  copy_out(&r.pointlist, s.points, got);
  copy_out(&r.pointmarkerlist, s.point_markers, got);
  copy_out(&r.trianglelist, s.triangles, got);
  copy_out(&r.triangleattributelist, s.triangle_attributes, got);
  copy_out(&r.trianglefacetlist, s.triangle_facets, got);
  copy_out(&r.edgelist, s.edges, got);
  copy_out(&r.edgemarkerlist, s.edge_markers, got);
  copy_out(&r.mergedpointlist, s.merged_points, got);
  copy_out(&r.emptiedfacetlist, s.emptied_facets, got);
  r.numberofmergedpoints = static_cast<int>(s.merged_points.size() / 2);
  r.numberofemptiedfacets = static_cast<int>(s.emptied_facets.size());
  r.budgetreached = s.budget_reached;
  r.roundsexhausted = s.rounds_exhausted;
  r.numberbelowangle = s.triangles_below_angle;
  r.numberabovearea = s.triangles_above_area;
  r.numberofpoints = s.point_count;
  r.numberoftriangles = s.triangle_count;
  r.numberofedges = s.edge_count;
  out = r;
}

}  // namespace
}  // namespace deltri

extern "C" {

int deltri_mesh_surface(const char* switches, const deltri_facets* in, deltri_surface* out, deltri_status* status) {
  return deltri::with_status(status, [&] {
    if (in == nullptr || out == nullptr) deltri::fail(DELTRI_USAGE_ERROR, "the input and output structs must not be NULL");
    const deltri::api::Surface surface = deltri::api::mesh_surface(deltri::facets_of(*in), switches ? switches : "");
    deltri::write_surface(surface, *out);
  });
}

void deltri_surface_free(deltri_surface* surface) {
  if (surface == nullptr) return;
  std::free(surface->pointlist);
  std::free(surface->pointmarkerlist);
  std::free(surface->trianglelist);
  std::free(surface->triangleattributelist);
  std::free(surface->trianglefacetlist);
  std::free(surface->edgelist);
  std::free(surface->edgemarkerlist);
  std::free(surface->mergedpointlist);
  std::free(surface->emptiedfacetlist);
  *surface = deltri_surface{};
}

}  // extern "C"
