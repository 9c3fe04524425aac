#include "cdt/flood.h"

namespace deltri {

std::vector<TriangleId> flood(const Mesh& mesh, std::vector<TriangleId> seeds,
                              std::vector<std::uint32_t>& marks, std::uint32_t mark) {
  std::vector<TriangleId>& stack = seeds;
  std::vector<TriangleId> reached;
  for (std::size_t i = 0; i < stack.size();) {
    // Drop seeds already marked, mark the rest, so each triangle enters the stack once.
    if (marks[stack[i]] == mark) {
      stack[i] = stack.back();
      stack.pop_back();
    } else {
      marks[stack[i++]] = mark;
    }
  }
  const bool constrained = mesh.has_subsegments();
  while (!stack.empty()) {
    const TriangleId t = stack.back();
    stack.pop_back();
    reached.push_back(t);
    for (unsigned i = 0; i < 3; ++i) {
      const EdgeRef e = edge_of(t, i);
      const EdgeRef f = mesh.link[e];
      if (f == kNone || (constrained && mesh.subseg.has(e))) continue;
      const TriangleId n = triangle_of(f);
      if (marks[n] == mark) continue;
      marks[n] = mark;
      stack.push_back(n);
    }
  }
  return reached;
}

}  // namespace deltri
