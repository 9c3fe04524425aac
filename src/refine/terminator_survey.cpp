// The Terminator's closing survey: the triangles still bad when refinement ends, for the report.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "refine/terminator.h"
#include "util/prefetch.h"
#include "util/run_both.h"

namespace deltri {

// The closing survey of slots [from, to) into `into`, whose survey fields start at zero.
void Terminator::survey(TriangleId from, TriangleId to, RefineReport& into) const {
  const double sin_theta = std::sqrt(opt_.angle.sin2());
  for (TriangleId t = from; t < to; ++t) {
    // The corners come in slot order, their points from anywhere: fetch those a few slots ahead.
    if (const TriangleId ahead{t + kSurveyPrefetch}; ahead < to && mesh_.is_live(ahead))
      for (unsigned i = 0; i < 3; ++i) prefetch(&mesh_.points[mesh_.corner[edge_of(ahead, i)]]);
    if (!mesh_.is_live(t)) continue;
    const SideMeasures m = side_measures(mesh_, t);
    if (quick_verdict_ && surely_good(m, rules_)) continue;
    const Assessment a = assess_with(t, rules_, m);  // the -q bound, also with Sec. 7.2's
    if (!a.bad()) continue;
    ++into.bad_triangles_left;
    into.obtuse_left += a.too_obtuse;
    if (a.too_large) {
      ++into.oversized_left;
      const double excess = size_excess(mesh_, t, a.shape, rules_);
      if (excess > into.worst_size_excess) {
        into.worst_size_excess = excess;
        into.worst_size_location = centroid_of(t);
      }
    }
    if (!a.skinny) continue;
    ++into.skinny_left;
    // r / l = sqrt(q) B with B = 1 / (2 sin theta).
    const double ratio = std::sqrt(a.shape.ratio2_over_bound2) / (2.0 * sin_theta);
    if (ratio < into.worst_ratio) continue;
    into.worst_ratio = ratio;
    into.worst_min_angle_deg = std::asin(std::min(1.0, 1.0 / (2.0 * ratio))) * 180.0 / std::numbers::pi;
    into.worst_location = centroid_of(t);
  }
}

// Assessing every triangle is about 4% of a large run: with a second thread, each takes half of
// the slots, and the upper half's findings are merged as a scan of all would have found them (the
// last of equally skinny triangles, the first of equally oversized ones).
void Terminator::survey_remaining() {
  const TriangleId slots{mesh_.triangle_slots()};
  RefineReport upper;
  run_halves(opt_.threads >= 2 && slots >= kParallelSurveySlots, TriangleId{0}, slots,
             [&](TriangleId from, TriangleId to, int half) {
               if (half == 0) return survey(from, to, report_);
               RefineReport mine;  // tallied on the worker's stack, apart from what this thread writes
               survey(from, to, mine);
               upper = std::move(mine);
             });
  report_.bad_triangles_left += upper.bad_triangles_left;
  report_.oversized_left += upper.oversized_left;
  report_.skinny_left += upper.skinny_left;
  report_.obtuse_left += upper.obtuse_left;
  if (upper.worst_size_excess > report_.worst_size_excess) {
    report_.worst_size_excess = upper.worst_size_excess;
    report_.worst_size_location = upper.worst_size_location;
  }
  if (upper.skinny_left > 0 && upper.worst_ratio >= report_.worst_ratio) {
    report_.worst_ratio = upper.worst_ratio;
    report_.worst_min_angle_deg = upper.worst_min_angle_deg;
    report_.worst_location = upper.worst_location;
  }
}

}  // namespace deltri
