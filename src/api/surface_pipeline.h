// The stages for facets in 3-D from a FacetInput to the finished surface mesh: the switches turned
// into facet options, every facet meshed so that shared segments agree (surface/surface_mesher.h),
// and -C (surface/check_surface.h). The one facade that the command line
// (src/cli/surface_run.cpp: files in, files out, messages) and the library (src/api/surface_library.cpp:
// arrays in, arrays out) both use. It reads and writes no file, prints nothing and never exits:
// errors are exceptions (pslg/errors.h; a facet that is not planar is an InputError naming it).
#pragma once

#include <optional>

#include "cli/switches.h"
#include "pslg/facets.h"
#include "surface/check_surface.h"
#include "surface/surface_mesher.h"

namespace deltri {

struct SurfaceResult {
  SurfaceMesh mesh;
  SurfaceReport report;
  std::optional<SurfaceCheck> check;  // with -C
  bool check_failed() const { return check && !check->ok(); }
};

// The switches mean the same for a facet as for a PSLG (-q, -a<number>, -u, -D, -Y, -S, the
// algorithm, the threads); the 2-D-only ones (-r, a bare -a, -A, -c, -v, -n, -o2, -j) are ignored.
SurfaceResult run_surface_pipeline(const FacetInput& input, const Switches& sw);

}  // namespace deltri
