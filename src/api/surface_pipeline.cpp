#include "api/surface_pipeline.h"

#include "api/pipeline.h"

namespace deltri {
namespace {

// A bare -a has no per-triangle bounds to use on facets, so those are switched off.
FacetMeshOptions facet_options(const Switches& sw) {
  FacetMeshOptions o;
  o.algorithm = sw.algorithm;
  o.threads = threads_to_use(sw);
  o.refine = sw.quality || sw.fixed_area || sw.user_test || sw.conforming_delaunay;
  o.refinement = refine_options(sw, false);
  o.refinement.size.triangle_bounds = false;
  return o;
}

}  // namespace

SurfaceResult run_surface_pipeline(const FacetInput& input, const Switches& sw) {
  SurfaceResult result;
  result.mesh = mesh_surface(input, facet_options(sw), result.report);
  if (sw.check) result.check = check_surface(result.mesh);
  return result;
}

}  // namespace deltri
