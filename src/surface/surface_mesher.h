// Meshing adjoining planar facets in 3-D (Shewchuk 2001, Sec. 7.1): every facet is meshed in its
// own plane coordinates by the 2-D pipeline (facet_mesher.h), and the facets agree on the
// vertices of every segment they share.
//
// How they come to agree, without a second Terminator: the facets are meshed, then every vertex
// a facet's refinement put on a shared segment is recorded as a parameter t along that segment,
// and every facet holding the segment is meshed again with the segment cut into pieces at all the
// recorded parameters (the pieces are input segments, their ends input vertices). This repeats
// until no facet adds a vertex on a shared segment. Then every facet's subsegments on a shared
// segment are exactly its pieces, the same in every facet: the meshes conform, and each piece's
// ends are one vertex in space (the point at t on the segment in 3-D, not each facet's rounded
// lift of it).
//
// Termination: the recorded points only grow, each is a vertex some facet's Terminator placed
// under its termination guard (so no piece gets shorter than that facet's edge floor), and a
// segment of finite length holds finitely many such points; so the rounds end. As a guard of its
// own, after kMaxSurfaceRounds the facets are meshed once more with no Steiner points on any
// segment (-YY): the result conforms, and triangles that miss the bounds are reported.
#pragma once

#include <cstdint>

#include "pslg/facets.h"
#include "surface/facet_mesher.h"
#include "surface/surface_mesh.h"

namespace deltri {

inline constexpr int kMaxSurfaceRounds = 40;

struct SurfaceReport {
  std::size_t segments = 0;         // distinct input segments
  std::size_t shared_segments = 0;  // held by two or more facets
  std::size_t shared_splits = 0;    // vertices on shared segments at the end
  int rounds = 0;                   // meshing rounds until the facets agreed
  std::size_t facet_meshings = 0;   // facet meshes made in all rounds
  bool converged = true;            // false: the -YY guard pass made the result
  RefineReport refine;              // summed over the facets' final meshes
  SegmentReport segment_repairs;    // summed likewise
};

// Throws InputError for a facet that is not planar (facet_plane.h).
SurfaceMesh mesh_surface(const FacetInput& input, const FacetMeshOptions& options, SurfaceReport& report);

}  // namespace deltri
