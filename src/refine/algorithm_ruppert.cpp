// Ruppert's algorithm (Sec. 3): diametral circles, circumcentres, midpoints, no deletion; Sec. 6.2's
// sure-fire rule where segments meet at under 60 degrees.
#include "refine/algorithm_policy.h"
#include "refine/refine.h"

namespace deltri {

AlgorithmPolicy ruppert_algorithm(const RefineOptions& opt) {
  AlgorithmPolicy p;
  p.rule = EncroachRule::circle();  // Sec. 3.1
  p.candidate_rule = p.rule;
  p.proof_rule = SplitRule::DiametralCircles;
  p.tracks_split_radii = true;
  // A subsegment is locked for what its neighbours were when its split failed: a vertex flush with
  // it, often one of a sliver between nearly collinear segments that later insertions replace. With
  // -D a subsegment left encroached keeps the mesh from being Delaunay (quality/conformity.h), so
  // once the queue is empty the encroached locked ones are unlocked and split where doubles now can;
  // each round ends the retries unless it split something (water.poly, ruppert -pDq20.7: 14 such
  // subsegments were left between vertices 1e-6 apart). The Terminator's -D meshes stay as they were
  // checked (on VVingerfly's test.poly the retries took its subsegments left not Delaunay from 627
  // to 6, and doubled the mesh).
  p.retries_locks = opt.conforming_delaunay;
  p.keeps_splits_inside = true;
  return p;
}

}  // namespace deltri
