// A previous mesh as read for -r (io/ele_file.h reads it; the library takes it from arrays):
// triangles as 0-based corner ids, with optional attributes. Plain data, here where the reader and
// cdt/rebuild_mesh.h may both see it.
#pragma once

#include <cstdint>
#include <vector>

namespace deltri {

struct EleData {
  std::uint32_t nodes_per_triangle = 3;
  int num_attributes = 0;
  std::vector<std::uint32_t> corners;  // nodes_per_triangle per triangle, 0-based vertex ids
  std::vector<double> attributes;      // num_attributes per triangle
  std::uint32_t triangle_count() const { return static_cast<std::uint32_t>(corners.size() / nodes_per_triangle); }
};

}  // namespace deltri
