#include "refine/algorithm.h"

#include "geometry/mesh_bounds.h"
#include "refine/termination_guard.h"

namespace deltri {

const char* refused_combination(RefinementAlgorithm algorithm, int interior_bound, bool quality,
                                bool conforming_delaunay, bool decline_cluster_splits) {
  if (algorithm == RefinementAlgorithm::Chew && conforming_delaunay)
    return "-D: Chew's second algorithm (--algorithm=chew) makes constrained Delaunay meshes only (Shewchuk "
           "2001, Sec. 4.1); for truly Delaunay triangles use --algorithm=ruppert";
  if (algorithm != RefinementAlgorithm::Terminator && decline_cluster_splits)
    return "--decline-cluster-splits: SPLITPERMITTED belongs to the Terminator (Fig. 38); Ruppert's and Chew's "
           "algorithms split every encroached subsegment";
  if (interior_bound != 0 && algorithm == RefinementAlgorithm::Terminator)
    return "--interior-bound: Sec. 7.2 strengthens Ruppert's or Chew's algorithm; give --algorithm=ruppert or "
           "--algorithm=chew";
  if (interior_bound != 0 && !quality)
    return "--interior-bound: give -q, the bound near segments (at most 20.7 with ruppert, 26.5 with chew for "
           "the paper's guarantee)";
  return nullptr;
}

StagePlan stage_plan(RefinementAlgorithm algorithm) {
  if (algorithm == RefinementAlgorithm::Terminator) return {kCascadeAngleDeg, kCascadeAllowance};
  return {kPaperModeReachDeg, kPaperModeAllowance};
}

}  // namespace deltri
