#include "io/output_numbering.h"

namespace deltri {

std::vector<std::uint32_t> number_live_triangles(const Mesh& mesh) {
  std::vector<std::uint32_t> numbers;
  if (mesh.free_triangles.empty()) return numbers;
  numbers.assign(mesh.triangle_slots(), kNone);
  std::uint32_t next = 0;
  for (TriangleId t = 0; t < mesh.triangle_slots(); ++t)
    if (mesh.is_live(t)) numbers[t] = next++;
  return numbers;
}

}  // namespace deltri
