// How mesh ids become the numbers written in output files. Shared by every writer so that .node,
// .ele, .poly, .edge and .neigh always agree.
#pragma once

#include <cstdint>
#include <vector>

#include "mesh/mesh.h"

namespace deltri {

// Vertex v is written as first_index + v, or, when a map is given (-j), as first_index + map[v];
// map[v] == kNone means v is not written at all.
struct VertexNumbering {
  const std::vector<std::uint32_t>* map = nullptr;
  int first_index = 1;

  bool written(VertexId v) const { return map == nullptr || (*map)[v] != kNone; }
  long long operator()(VertexId v) const {
    return static_cast<long long>(map ? (*map)[v] : v) + first_index;
  }
};

// Live triangles are numbered consecutively in slot order (dead slots are skipped), from 0.
// Empty result means "slot t is number t" (no dead slots), to save the array in the common case.
std::vector<std::uint32_t> number_live_triangles(const Mesh& mesh);

inline std::uint32_t triangle_number(const std::vector<std::uint32_t>& numbers, TriangleId t) {
  return numbers.empty() ? t : numbers[t];
}

}  // namespace deltri
