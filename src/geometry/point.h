// A point of the plane. Plain data: the algorithms decide everything with exact predicates on
// these doubles, never with tolerances.
#pragma once

namespace deltri {

struct Point {
  double x = 0.0;
  double y = 0.0;
  friend bool operator==(const Point&, const Point&) = default;
};

}  // namespace deltri
