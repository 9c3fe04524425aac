// Range-restricted segment splitting (Sec. 7.3, range_restricted.h) on top of any algorithm: every
// subsegment not at a shell apex follows the ladder of legal lengths, mirrored points (which leave
// arbitrary lengths) are not used, and Sec. 6.2's sure-fire rule covers the small input angles that
// Theorem 13 does not.
#include "refine/algorithm_policy.h"

namespace deltri {

void restrict_split_ranges(AlgorithmPolicy& policy) {
  policy.legal_lengths = true;
  policy.mirrors = false;
  policy.tracks_split_radii = true;
  policy.provable = false;
}

}  // namespace deltri
