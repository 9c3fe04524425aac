// What became of one bad triangle or one encroached subsegment when the Terminator served it:
// the core (terminator_core.cpp) returns one of these for each, and count() turns it into the
// report's counters in one place.
#pragma once

#include <cstdint>

#include "refine/refine.h"

namespace deltri {

enum class Outcome : std::uint8_t {
  Inserted,  // Fig. 38 l.16: the triangle's point is a new vertex
  Split,     // Fig. 39 l.44: the subsegment is split
  Deferred,  // Fig. 38 l.18-25: the point encroached; subsegments were queued and split instead
  NotBad,    // the triangle meets the bounds now
  Gone,      // Fig. 38 l.12, Fig. 39 l.38: the triangle or subsegment is no longer in the mesh
  // Refused, and why:
  OverBudget,      // the Steiner cap or -S
  BelowFloor,      // the guard: the new edges would be shorter than its floor
  Hopeless,        // no double gives the triangle's shortest edge a good triangle (bottom_scale.h)
  NoBetterDouble,  // no double near the point improves the triangles it would destroy
  NoPoint,         // the circumcentre is not finite (a triangle flat to rounding)
  Unusable,        // the probe found no place for the point
  KeptBoundary,    // -Y/-YY: the point would spoil the triangles next to a kept boundary (KeptBoundary, kept_boundary.h)
  OnSubsegment,    // the point lies on a subsegment that may not be split
  Declined,        // SPLITPERMITTED (Fig. 38 l.21) refused every encroached subsegment
  Locked,          // doubles cannot split the subsegment: it is kept whole from now on
  InteriorBoundAtBottom,  // bad only for Sec. 7.2's 30 degrees, at the bottom of double precision
  SureFire,  // Ruppert, Chew: the split would have a smaller insertion radius than the split on an incident
             // segment that encroaches (Sec. 6.2's rule, Terminator::refused_by_sure_fire_rule)
};

constexpr bool refused(Outcome o) { return o >= Outcome::OverBudget; }

// Adds the outcome to the report's counters.
void count(Outcome o, RefineReport& report);

}  // namespace deltri
