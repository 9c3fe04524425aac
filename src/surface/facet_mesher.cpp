#include "surface/facet_mesher.h"

#include "cdt/holes_and_regions.h"
#include "cdt/insert_segments.h"

namespace deltri {

FacetMeshResult mesh_facet(Pslg pslg, const FacetMeshOptions& options) {
  FacetMeshResult result;
  Mesh& mesh = result.mesh;
  mesh.kind.assign(pslg.points.size(), VertexKind::Input);
  mesh.points = std::move(pslg.points);
  // One thread per facet: facets are small, and the result must not depend on the thread count.
  const DelaunayReport dt = delaunay_triangulate(mesh, options.algorithm, 1);
  Predicates pred;
  result.segments = insert_segments(mesh, pred, pslg.segments, dt.duplicates, true);
  carve_holes(mesh, pred, pslg.holes, false);
  if (options.refine && mesh.live_triangles() > 0) {
    RefineOptions opt = options.refinement;
    opt.threads = 1;
    result.refine = refine_mesh(mesh, pred, opt);
    mesh.compact_triangles();
  }
  return result;
}

}  // namespace deltri
