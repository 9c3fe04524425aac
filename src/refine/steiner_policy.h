// Where a bad triangle's Steiner point goes (--steiner, -k): a setting of the refinement core, read
// by Terminator::choose_point (refine/steiner_point.h).
#pragma once

#include <cstdint>

namespace deltri {

enum class SteinerPolicy : std::uint8_t {
  Automatic,     // off-centres up to kOptimalAboveDeg, locally optimal points above it
  OffCentre,     // Ungor's off-centre (Shewchuk 2001, Sec. 6.4), or the circumcentre when nearer
  Circumcentre,  // the circumcentre (-k)
  Optimal,       // Erten and Ungor's locally optimal point in the petal of the shortest edge
};

// Above this -q, Automatic chooses locally optimal points: there they reach bounds off-centres
// cannot (docs/refinement.md, "Locally optimal Steiner points"); at and below it the meshes are
// the off-centres' as they always were.
inline constexpr double kOptimalAboveDeg = 34.0;

inline SteinerPolicy resolved_policy(SteinerPolicy asked, double angle_deg) {
  if (asked != SteinerPolicy::Automatic) return asked;
  return angle_deg > kOptimalAboveDeg ? SteinerPolicy::Optimal : SteinerPolicy::OffCentre;
}

}  // namespace deltri
