// -Y / -YY, once Q_t is empty (mending.cpp): the triangles left below the bound next to a kept
// boundary, worst first, get a point across their longest edge where that betters every triangle
// it replaces. A policy of its own, chosen once from RefineOptions: the driver calls run() after
// the queue drains, and without -Y it returns at once.
#pragma once

#include <cmath>
#include <cstddef>
#include <vector>

#include "geometry/point.h"
#include "mesh/mesh.h"
#include "refine/criteria.h"

namespace deltri {

struct RefineOptions;
class Terminator;

class Mending {
 public:
  explicit Mending(const RefineOptions& opt);
  void run(Terminator& term);

 private:
  bool mend(Terminator& term, TriangleId t);
  double score(Terminator& term, TriangleId t, const Assessment& assessed, const Point& q);
  struct Tally {
    double worst_sine2 = 1.0;  // of the smallest angles
    std::size_t below_angle = 0, over_size = 0;
    double tightest_area = HUGE_VAL;  // the least area bound among them
  };
  Tally tally_replaced(Terminator& term);
  Tally tally_made(Terminator& term, const Point& q, double tightest_area) const;
  static constexpr int kMendRounds = 4;

  bool active_ = false;
  std::vector<TriangleId> scratch_;  // tally_replaced's list
};

}  // namespace deltri
