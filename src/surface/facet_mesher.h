// One facet through the unchanged 2-D pipeline: Delaunay triangulation of its points in plane
// coordinates, its segments (constrained Delaunay), its holes and the outside carved away, then
// (optionally) Terminator refinement with the run's bounds.
#pragma once

#include "cdt/insert_segments.h"
#include "delaunay/triangulate.h"
#include "mesh/mesh.h"
#include "pslg/pslg.h"
#include "refine/refine.h"

namespace deltri {

struct FacetMeshOptions {
  DelaunayAlgorithm algorithm = DelaunayAlgorithm::DivideAndConquer;
  bool refine = false;  // run refine_mesh with `refinement`
  RefineOptions refinement;
  int threads = 1;      // > 1: facets are meshed two at a time (each facet on one thread)
  // -S: the Steiner points the whole surface run may add, over every facet and every round
  // (surface_mesher.h); -1 unlimited. refinement.max_steiner is set per facet meshing from it.
  long steiner_total = -1;
};

struct FacetMeshResult {
  Mesh mesh;               // compacted: every triangle slot live
  RefineReport refine;     // zero when not refined
  SegmentReport segments;  // what the constrained Delaunay stage repaired
};

// `pslg` is consumed (its points move into the mesh). Vertex ids below pslg.points.size() are
// the PSLG's points; later ones were added (segment crossings, refinement).
FacetMeshResult mesh_facet(Pslg pslg, const FacetMeshOptions& options);

}  // namespace deltri
