// Chew's second algorithm (Sec. 4): circumcentres; a subsegment between a bad triangle and its
// circumcentre, or under it, is split at its midpoint after every free vertex in its diametral
// circle is deleted; Sec. 6.2's sure-fire rule with both ends of the requesting triangle's
// shortest edge, and the vertex across the wedge, as ancestors (terminator_policies.cpp).
#include "refine/algorithm_policy.h"
#include "refine/refine.h"

namespace deltri {

AlgorithmPolicy chew_algorithm(const RefineOptions& opt) {
  AlgorithmPolicy p;
  // Chew splits a subsegment only when it lies between a bad triangle and its circumcentre, which
  // the probe's walk finds whatever the rule (candidate_probe.h), or when the circumcentre lies on
  // it (Sec. 4.1): the lens of 0 degrees, the open subsegment itself (with no angle bound the
  // Terminator's least lens).
  p.rule = EncroachRule::lens(opt.angle.degrees() > 0.0 ? 0.0 : kLeastLensDeg);
  p.candidate_rule = p.rule;
  p.proof_rule = SplitRule::Chew;
  p.deletes_before_split = true;
  p.deletes_every_free_vertex = true;
  p.tracks_split_radii = true;
  p.chew_ancestors = true;
  p.retries_locks = opt.conforming_delaunay;  // -D is refused with Chew's (algorithm.cpp)
  p.keeps_splits_inside = true;
  return p;
}

}  // namespace deltri
