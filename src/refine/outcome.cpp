#include "refine/outcome.h"

namespace deltri {

void count(Outcome o, RefineReport& report) {
  const auto guard = [&report] {
    ++report.guard_refusals;
    report.stopped_by_guard = true;
  };
  switch (o) {
    case Outcome::Inserted: ++report.interior_steiner; break;
    case Outcome::Split:
      ++report.segment_steiner;
      ++report.encroached_splits;
      break;
    case Outcome::Deferred: ++report.rejected_candidates; break;
    case Outcome::Declined:
      ++report.rejected_candidates;
      ++report.declined_splits;
      break;
    case Outcome::BelowFloor: guard(); break;
    case Outcome::Hopeless:
    case Outcome::NoBetterDouble:
      ++report.bottom_scale_refusals;
      guard();
      break;
    case Outcome::KeptBoundary: ++report.kept_boundary_refusals; break;
    case Outcome::Locked: ++report.locked_subsegments; break;
    case Outcome::InteriorBoundAtBottom: ++report.interior_bound_refusals; break;
    case Outcome::SureFire:
      ++report.sure_fire_refusals;
      guard();
      break;
    case Outcome::NotBad:
    case Outcome::Gone:
    case Outcome::OverBudget:  // budget_left() raised its flag
    case Outcome::NoPoint:
    case Outcome::Unusable:
    case Outcome::OnSubsegment: break;
  }
}

}  // namespace deltri
