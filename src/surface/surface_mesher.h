// Meshing adjoining planar facets in 3-D (Shewchuk 2001, Sec. 7.1): every facet is meshed in its
// own plane coordinates by the 2-D pipeline (facet_mesher.h), and the facets agree on the
// vertices of every segment they share.
//
// How they come to agree, without a second Terminator: the facets are meshed, then every vertex
// a facet's refinement put on a shared segment is recorded as a parameter t along that segment,
// and every facet holding the segment is meshed again with the segment cut into pieces at all the
// recorded parameters (the pieces are input segments, their ends input vertices), and with the
// interior vertices of its previous mesh as seeds, so that it is re-meshed from nearly the mesh it
// had and only the neighbourhood of the new cuts changes. This repeats
// until no facet adds a vertex on a shared segment. Then every facet's subsegments on a shared
// segment are exactly its pieces, the same in every facet: the meshes conform, and each piece's
// ends are one vertex in space (the point at t on the segment in 3-D, not each facet's rounded
// lift of it).
//
// Termination: the recorded points only grow, and each is a vertex a facet's Terminator placed
// under its termination guard. That guard's floor is tied to the facet's input, which the cuts
// arriving from other facets extend, so the rounds are not proven to end (docs/surfaces.md); they
// are bounded instead: after kMaxSurfaceRounds the run starts again from the facets as read with
// one tree of split points per segment (surface_mesher.cpp, "the second try"), and after
// kMaxSurfaceRounds more the facets are meshed once more with no Steiner points on any segment
// (-YY), which always conforms; triangles that miss the bounds are reported.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "pslg/facets.h"
#include "surface/facet_mesher.h"
#include "surface/surface_mesh.h"

namespace deltri {

inline constexpr int kMaxSurfaceRounds = 40;

// One meshing round, as it ends (-V).
struct SurfaceRound {
  int round = 0;
  std::size_t facets_meshed = 0;    // in this round
  std::size_t steiner = 0;          // Steiner points of the surface so far
  long budget = -1;                 // the run's Steiner budget (-1: not set yet, round 1 without -S)
  std::size_t shared_splits = 0;    // vertices on shared segments so far
  std::size_t to_mesh_again = 0;    // facets the next round meshes
};
using SurfaceProgress = std::function<void(const SurfaceRound&)>;

struct SurfaceReport {
  std::size_t segments = 0;         // distinct input segments
  std::size_t shared_segments = 0;  // held by two or more facets
  std::size_t shared_splits = 0;    // vertices on shared segments at the end
  int rounds = 0;                   // meshing rounds until the facets agreed (of the second try if it ran)
  std::size_t facet_meshings = 0;   // facet meshes made in all rounds
  bool converged = true;            // false: the -YY guard pass made the result
  // The run's Steiner budget: -S if given, and never more than the sum of the caps the 2-D guard
  // (refine/termination_guard.h) gave the facets in the first round, nor than the memory budget
  // holds. The facets and the rounds draw on it together (-S strictly, by equal shares per round;
  // the guard's total by ending the rounds once reached); then a last -YY pass makes them agree.
  long steiner_budget = -1;         // -1: none was needed (no refinement)
  bool budget_reached = false;      // the rounds ended on the budget (or a facet's share of -S stopped it)
  std::size_t steiner_total = 0;    // Steiner points of the final surface
  std::vector<std::uint32_t> emptied_facets;  // facets (0-based) whose hole points left no triangle
  RefineReport refine;              // summed over the facets' final meshes
  SegmentReport segment_repairs;    // summed likewise
};

// Throws InputError for a facet that is not planar (facet_plane.h). `max_rounds` is the guard's
// round cap (smaller only in tests of the guard).
SurfaceMesh mesh_surface(const FacetInput& input, const FacetMeshOptions& options, SurfaceReport& report,
                         int max_rounds = kMaxSurfaceRounds, const SurfaceProgress& progress = {});

}  // namespace deltri
