// The smallest axis-aligned box around the points added to it.
#pragma once

#include <algorithm>
#include <cmath>

#include "geometry/point.h"

namespace deltri {

struct Box {
  double lo_x = HUGE_VAL, lo_y = HUGE_VAL, hi_x = -HUGE_VAL, hi_y = -HUGE_VAL;

  void add(const Point& p) {
    lo_x = std::min(lo_x, p.x), lo_y = std::min(lo_y, p.y);
    hi_x = std::max(hi_x, p.x), hi_y = std::max(hi_y, p.y);
  }
  void merge(const Box& b) {  // the box around both
    if (b.empty()) return;
    add(Point{b.lo_x, b.lo_y});
    add(Point{b.hi_x, b.hi_y});
  }
  bool empty() const { return !(lo_x <= hi_x); }  // nothing added yet
  double width() const { return hi_x - lo_x; }
  double height() const { return hi_y - lo_y; }
};

}  // namespace deltri
