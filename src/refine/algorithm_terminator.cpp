// The Terminator (Sec. 6.3-6.4, Appendix A): diametral lenses, off-centres, concentric shells and
// mirrored split points, Chew's step with lenses, the equal-shell exemption.
#include <algorithm>

#include "refine/algorithm_policy.h"
#include "refine/refine.h"

namespace deltri {
namespace {

// A candidate Steiner point is tested against a lens never flatter than that of 20 degrees. With
// a lower angle bound, or none (-a, -u alone), the bound's own lens let free points settle a
// hair's breadth from a segment and left slivers of 0.01 degrees beside it; with this one such a
// point splits the subsegment instead, and size-bounded meshes keep their angles near 20 degrees
// away from small input angles, at about the same triangle count (docs/refinement.md, "Area
// bounds alone"). Only candidates: the vertices already there (the input's among them) are held
// to the bound's own lens, or a size bound alone would split every segment an input vertex
// stands near, as a -q20 mesh does. At 20 degrees and above the two lenses are one.
constexpr double kLeastCandidateLensDeg = 20.0;

EncroachRule candidate_rule_for(const EncroachRule& rule) {
  if (rule.min_apex_angle_deg <= 90.0) return rule;
  const EncroachRule floor = EncroachRule::lens(kLeastCandidateLensDeg);
  return floor.min_apex_angle_deg < rule.min_apex_angle_deg ? floor : rule;
}

}  // namespace

AlgorithmPolicy terminator_algorithm(const RefineOptions& opt) {
  AlgorithmPolicy p;
  const bool lenses = opt.lenses && !opt.conforming_delaunay;
  p.rule = lenses ? EncroachRule::lens(std::max(opt.angle.degrees(), kLeastLensDeg)) : EncroachRule::circle();
  p.candidate_rule = candidate_rule_for(p.rule);
  p.proof_rule = p.rule.min_apex_angle_deg == 90.0 ? SplitRule::DiametralCircles : SplitRule::DiametralLenses;
  p.off_center_factor = opt.off_centers ? opt.angle.off_center_factor() : 0.0;
  p.shells = true;
  p.mirrors = true;
  p.deletes_before_split = lenses;
  p.shell_exemption = true;
  return p;
}

}  // namespace deltri
