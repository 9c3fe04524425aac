// Where a bad triangle's Steiner point goes (--steiner, -k): a setting of the refinement core, read
// by Terminator::choose_point (refine/steiner_point.h).
#pragma once

#include <cstdint>

namespace deltri {

enum class SteinerPolicy : std::uint8_t {
  Automatic,     // off-centres below kOptimalFromDeg, locally optimal points from it (resolved_policy)
  OffCentre,     // Ungor's off-centre (Shewchuk 2001, Sec. 6.4), or the circumcentre when nearer
  Circumcentre,  // the circumcentre (-k)
  Optimal,       // Erten and Ungor's locally optimal point in the petal of the shortest edge
};

// Above kOptimalAboveDeg, Automatic chooses locally optimal points: there they reach bounds
// off-centres cannot (docs/refinement.md, "Locally optimal Steiner points"). From kOptimalFromDeg
// it chooses them too, for they make fewer triangles there (no corpus file above 1.05 times
// Triangle's count at -q33, where off-centres left four), except when -Y or -YY keep the boundary
// whole: there locally optimal points left thinner triangles than Triangle's at -q33 (river.poly
// -YY: 2.44 degrees against 2.838). Below kOptimalFromDeg the meshes are the off-centres' as they
// always were.
inline constexpr double kOptimalAboveDeg = 34.0;
inline constexpr double kOptimalFromDeg = 33.0;

// keeps_boundary: -Y or -YY (keeps_boundary in kept_boundary.h).
inline SteinerPolicy resolved_policy(SteinerPolicy asked, double angle_deg, bool keeps_boundary) {
  if (asked != SteinerPolicy::Automatic) return asked;
  if (angle_deg > kOptimalAboveDeg || (angle_deg >= kOptimalFromDeg && !keeps_boundary)) return SteinerPolicy::Optimal;
  return SteinerPolicy::OffCentre;
}

}  // namespace deltri
