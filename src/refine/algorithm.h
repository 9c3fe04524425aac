// Which algorithm of Shewchuk 2001 the one refinement core (terminator_core.cpp) runs, and the
// stronger bound away from segments of Sec. 7.2. They are policies, not separate programs: the
// core asks terminator_policies.cpp where a point goes, when a subsegment counts as encroached,
// which splits are permitted and whether Chew's step deletes vertices, and those answers read
// the table each algorithm fills once (algorithm_policy.h; docs/refinement.md, "The policies").
#pragma once

#include <cstdint>

namespace deltri {

enum class RefinementAlgorithm : std::uint8_t {
  Terminator,  // Sec. 6.3-6.4 and Appendix A: lenses, concentric shells, Chew's step (the default)
  Ruppert,     // Sec. 3: diametral circles, circumcentres, midpoints, no deletion
  Chew,        // Sec. 4: a subsegment between a bad triangle and its circumcentre is split at its
               // midpoint after the free vertices in its diametral circle are deleted
};

// How refinement goes past what an algorithm reaches (refine/refine.cpp, refine_in_stages): up to
// reach_deg in one stage; above it, first to reach_deg, then on at the asked bound with at most
// allowance Steiner points per vertex of that mesh, taken back if the allowance runs out. The
// Terminator reaches kCascadeAngleDeg (34 degrees) on every input measured, with an allowance of
// kCascadeAllowance (refine/termination_guard.h). Ruppert's and Chew's algorithms, with no shells or
// lenses at small input angles and proven only to 20.7 and 26.6 degrees, reach 33 on the whole
// corpus but ran to the Steiner cap at 34 on 11 of its 51 smaller files, and where they do go on
// past 33 they cascade (Chew on river: 3 times its -q33 triangles at -q34), so their allowance is one
// point per vertex (docs/refinement.md, "The paper's modes near their limits").
struct StagePlan {
  double reach_deg;
  double allowance;
};
inline constexpr double kPaperModeReachDeg = 33.0;
inline constexpr double kPaperModeAllowance = 1.0;
StagePlan stage_plan(RefinementAlgorithm algorithm);

// Sec. 7.2: B = 1, that is 30 degrees, away from segments.
inline constexpr double kInteriorBoundDeg = 30.0;

// Why the paper rules a combination out, as one line, or nullptr when it is allowed.
// interior_bound: 0 (none), 1 or 2 (Sec. 7.2's strategies); quality: -q was given.
const char* refused_combination(RefinementAlgorithm algorithm, int interior_bound, bool quality,
                                bool conforming_delaunay, bool decline_cluster_splits);

}  // namespace deltri
