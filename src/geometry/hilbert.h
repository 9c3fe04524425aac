// Positions along a Hilbert curve laid over a box. Points close on the curve are close in the
// plane, so visiting points in curve order keeps each walk from the previous point short (the
// incremental Delaunay insertion order, the location of hole and region points).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "geometry/box.h"
#include "geometry/point.h"

namespace deltri {

class HilbertCurve {
 public:
  // A 2^16 x 2^16 grid over the square whose corner is the box's lower left and whose side is the
  // box's longer one.
  explicit HilbertCurve(const Box& box);
  // The position of p's grid cell along the curve (points outside the box clamp to its edge).
  std::uint32_t key(const Point& p) const;

 private:
  double lo_x_, lo_y_, scale_;
};

// The indices of `points` in curve order over their box, ties in index order.
std::vector<std::uint32_t> hilbert_order(std::span<const Point> points);

}  // namespace deltri
