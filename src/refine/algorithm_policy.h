// The algorithm of Shewchuk 2001 that the one refinement core (terminator_core.cpp) runs, as a
// plain table of rules chosen once, when a Terminator is built: which vertices encroach, where a
// subsegment is split, whether Chew's step deletes vertices first, which triangles the equal-shell
// exemption spares, which vertices are a split's ancestors for Sec. 6.2's sure-fire rule. Each
// algorithm fills the table in a file of its own (algorithm_terminator.cpp, algorithm_ruppert.cpp,
// algorithm_chew.cpp; range-restricted splitting, Sec. 7.3, amends any of them in
// algorithm_range_restricted.cpp). The Terminator reads the table's values and never asks which
// algorithm it runs: a new rule is a new field, a new algorithm a new file, and the core loop is
// not edited for either (docs/refinement.md, "The paper's algorithms").
#pragma once

#include "geometry/encroachment.h"
#include "refine/algorithm.h"
#include "refine/termination_guard.h"

namespace deltri {

struct RefineOptions;

struct AlgorithmPolicy {
  // Whether a vertex already in the mesh encroaches upon a subsegment (Fig. 39 l.46, l.52).
  EncroachRule rule = EncroachRule::circle();
  // Whether a candidate Steiner point does (Fig. 38 l.14): rule, or a lens never flatter than 20
  // degrees for the Terminator (algorithm_terminator.cpp).
  EncroachRule candidate_rule = EncroachRule::circle();
  // The rule the paper's termination proofs are stated for (termination_guard.h).
  SplitRule proof_rule = SplitRule::DiametralCircles;
  // False where no theorem of the paper covers the algorithm whatever the input (Sec. 7.3).
  bool provable = true;
  // The off-centre factor (Sec. 6.4) for bad triangles' Steiner points; 0: circumcentres.
  double off_center_factor = 0.0;
  // Fig. 39 l.39: concentric shells at the apices that use them (Sec. 6.3); mirrored split points
  // across thin wedges (mirrored_split.h); the ladder of legal lengths elsewhere (Sec. 7.3). With
  // none of them, the midpoint.
  bool shells = false;
  bool mirrors = false;
  bool legal_lengths = false;
  // Fig. 39 l.40-43, Chew's step: free vertices in the diametral circle are deleted before a
  // split; every one of them (Chew's own rule, Sec. 4.1), or only those too close to the split
  // point (chew_step.cpp, too_close_to_split).
  bool deletes_before_split = false;
  bool deletes_every_free_vertex = false;
  // Sec. 6.2's sure-fire rule: insertion radii of splits are kept, and a split refused where it
  // would be smaller than an ancestor's. chew_ancestors: both ends of the requesting triangle's
  // shortest edge count, and the vertex the radius is measured to (Chew in thin wedges).
  bool tracks_split_radii = false;
  bool chew_ancestors = false;
  // Miller, Pav and Walkington's equal-shell exemption of skinny triangles at small junctions.
  bool shell_exemption = false;
  // -D: the locked subsegments left encroached are tried again once the queue is empty.
  bool retries_locks = false;
  // Bottom-scale split points on the boundary are kept on the mesh's side of the subsegment.
  bool keeps_splits_inside = false;
  // Sec. 7.2 (--interior-bound, Ruppert and Chew): 0, none; 1, the triangles with no corner in a
  // segment interior are held to max(-q, 30 degrees); 2, every triangle is, and one bad for the 30
  // degrees alone splits an encroached subsegment only where |s|/2 is at least its shortest edge.
  int interior_strategy = 0;
  // Fig. 38 l.21: SPLITPERMITTED decides which subsegments a rejected point may have split
  // (--decline-cluster-splits, the Terminator's); else every one.
  bool declines_cluster_splits = false;

  // The table for opt.algorithm and opt's switches.
  static AlgorithmPolicy of(const RefineOptions& opt);
};

// Each algorithm's table (one file each).
AlgorithmPolicy terminator_algorithm(const RefineOptions& opt);
AlgorithmPolicy ruppert_algorithm(const RefineOptions& opt);
AlgorithmPolicy chew_algorithm(const RefineOptions& opt);
// Sec. 7.3 on top of any of them.
void restrict_split_ranges(AlgorithmPolicy& policy);

// Without an angle bound (-a, -u alone) the lens would shrink to the subsegment itself, and a
// Steiner point exactly on a segment's line, beside a split vertex that rounding put an ulp off
// it, would encroach upon nothing: it made triangles of 1e-13 degrees (guitar.poly -pa0.003). A
// lens of 0.01 degrees catches such points and lets every other one be.
inline constexpr double kLeastLensDeg = 0.01;

// How refinement goes past what opt's algorithm reaches (algorithm.h, StagePlan).
StagePlan stage_plan(const RefineOptions& opt);

}  // namespace deltri
