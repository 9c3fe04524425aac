// A uniform grid over the bounding boxes of a set of triangles: for a point, the triangles whose
// box meets its cell (the point clamped into the grid). Point location in a fixed background
// mesh (refine/area_field.h, refine/size_field.h) without walking its topology.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "geometry/box.h"

namespace deltri {

class TriangleGrid {
 public:
  TriangleGrid() = default;
  // boxes[i] is triangle i's box, `all` their union, `cell` the side of a square cell.
  TriangleGrid(const std::vector<Box>& boxes, const Box& all, double cell);

  std::span<const std::uint32_t> near(const Point& p) const;
  double lo_x() const { return lo_x_; }
  double lo_y() const { return lo_y_; }
  double cell_size() const { return cell_size_; }

 private:
  std::size_t cell_of(double x, double y) const;
  std::vector<std::uint32_t> cell_start_;  // triangles of cell i: cell_list_[cell_start_[i] .. [i+1])
  std::vector<std::uint32_t> cell_list_;
  double lo_x_ = 0.0, lo_y_ = 0.0, cell_size_ = 1.0;
  std::size_t columns_ = 1, rows_ = 1;
};

}  // namespace deltri
