// The bounds a quality mesh is asked to meet, each made once from the switches (pipeline/pipeline.cpp)
// into one Criteria (refine/criteria.h) that refinement and the account of misses
// (quality/bound_misses.h) both read: the smallest angle theta (-q) with every quantity derived
// from it, the largest angle (--max-angle), and the size bounds (-a, -u).
#pragma once

#include <cmath>
#include <numbers>

#include "util/invariant.h"

namespace deltri {

// Above this angle bound Delaunay refinement is not proven to terminate and can cascade (Sec. 7.3,
// Fig. 37): refinement goes there in two stages (refine/refine.cpp) under a tighter Steiner cap
// and an unscaled guard floor (refine/termination_guard.h).
inline constexpr double kCascadeAngleDeg = 34.0;

class AngleBound {
 public:
  AngleBound() = default;  // none asked (no -q)
  // -q theta; theta = 0 asks for refinement with no angle bound.
  explicit AngleBound(double theta_deg) : asked_(true), degrees_(theta_deg) {
    DELTRI_ASSERT(theta_deg < 60.0);  // no triangle has a smallest angle above 60 degrees
    if (!(theta_deg > 0.0)) {
      degrees_ = 0.0;
      return;
    }
    const double s = std::sin(theta_deg * std::numbers::pi / 180.0);
    sin2_ = s * s;
    off_center_factor_ = 0.475 / std::tan(0.5 * theta_deg * std::numbers::pi / 180.0);
  }
  bool asked() const { return asked_; }         // -q was given
  double degrees() const { return degrees_; }   // theta, 0 when there is no angle bound
  // sin^2 theta: a triangle is skinny when its circumradius-to-shortest-edge ratio exceeds
  // 1 / (2 sin theta) (refine/criteria.h); 0 turns the angle test off.
  double sin2() const { return sin2_; }
  // 0.475 cot(theta / 2): the off-centre's height over the shortest edge, in edge lengths
  // (geometry/constructions.h). (1/2) cot(theta / 2) makes the new triangle's apex angle exactly
  // theta; 0.95 of it, as the reference does, makes it a little better than the bound. 0 without
  // an angle bound.
  double off_center_factor() const { return off_center_factor_; }
  // Beyond kCascadeAngleDeg.
  bool cascades() const { return degrees_ > kCascadeAngleDeg; }

 private:
  bool asked_ = false;
  double degrees_ = 0.0;
  double sin2_ = 0.0;
  double off_center_factor_ = 0.0;
};

// The largest-angle bound (--max-angle=A, 90 <= A < 180): a triangle whose largest angle exceeds A
// is bad unless that angle lies between two subsegments (the input forces it). An angle at p
// between rays to a and b exceeds A exactly when (a - p).(b - p) < |a - p| |b - p| cos A; cos A <= 0,
// so when the dot product is negative and its square exceeds cos^2 A |a - p|^2 |b - p|^2
// (refine/criteria.h evaluates it exactly; cos2() is the double that test compares against).
class LargestAngleBound {
 public:
  LargestAngleBound() = default;  // none asked
  explicit LargestAngleBound(double degrees) : degrees_(degrees) {
    DELTRI_ASSERT(degrees >= 90.0 && degrees < 180.0);
    const double c = std::cos(degrees * std::numbers::pi / 180.0);
    cosine_ = degrees == 90.0 ? 0.0 : c;
    cos2_ = cosine_ * cosine_;
  }
  bool asked() const { return degrees_ > 0.0; }
  double degrees() const { return degrees_; }  // 0: none
  double cosine() const { return cosine_; }    // cos A, at most 0; exactly 0 for A = 90
  double cos2() const { return cos2_; }

 private:
  double degrees_ = 0.0;
  double cosine_ = 0.0;
  double cos2_ = 0.0;
};

// The size bounds: a triangle is too large when its area exceeds max_area or its own bound, or an
// edge is longer than max_edge_length.
struct SizeBounds {
  double max_area = 0.0;         // -a with a number; <= 0: none
  bool triangle_bounds = false;  // each triangle's own area bound (mesh.area_bound: -a alone, regions, .area)
  double max_edge_length = 0.0;  // -u; <= 0: none
  bool any() const { return max_area > 0.0 || triangle_bounds || max_edge_length > 0.0; }
};

}  // namespace deltri
