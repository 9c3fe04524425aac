// The stages for facets in 3-D from a FacetInput to the finished surface mesh: the switches turned
// into facet options, every facet meshed so that shared segments agree (surface/surface_mesher.h),
// and -C (surface/check_surface.h). The one facade that the command line
// (src/cli/surface_run.cpp: files in, files out, messages) and the library (src/api/surface_library.cpp:
// arrays in, arrays out) both use. It reads and writes no file, prints nothing and never exits:
// errors are exceptions (util/errors.h; a facet that is not planar is an InputError naming it).
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "options/options.h"
#include "pslg/facets.h"
#include "surface/check_surface.h"
#include "surface/surface_mesher.h"

namespace deltri {

struct SurfaceResult {
  SurfaceMesh mesh;
  SurfaceReport report;
  // -C's check, run on every mesh: a run ends well only with a mesh the check accepts (facets
  // whose loops cross other loops or segments give subsegments that are no edge of their facet).
  std::optional<SurfaceCheck> check;
  // Input points (0-based) with the coordinates of an earlier one, each with the point it was
  // merged into.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> merged;
  // When the round cap or the Steiner budget ended the run: the triangles below the -q angle and
  // above the -a area.
  std::size_t below_angle = 0, above_area = 0;
  bool check_failed() const { return check && !check->ok(); }
};

// The switches mean the same for a facet as for a PSLG (-q, -a<number>, -u, -D, -Y, -S, the
// algorithm, the threads); the 2-D-only ones (-r, a bare -a, -A, -c, -v, -n, -o2, -j) are ignored.
// `progress`, if set, hears of each meshing round as it ends (-V). Points with the coordinates of an
// earlier point are merged into it (`merged`); an input whose coordinates are very large or very
// small is meshed scaled by a power of two, and the mesh scaled back.
SurfaceResult run_surface_pipeline(const FacetInput& input, const Options& sw, const SurfaceProgress& progress = {});

// Loud, counted statements of what the result is not, one line each, word for word as the command
// line prints them after "deltri: warning: " and the library returns them: merged points, facets
// left empty, and the round cap's or the Steiner budget's misses. Point and facet numbers count
// from `first`.
std::vector<std::string> surface_warnings(const SurfaceResult& result, const Options& sw, int first);

// The smallest angle of a triangle in space, in degrees.
double surface_smallest_angle(const Point3& a, const Point3& b, const Point3& c);

}  // namespace deltri
