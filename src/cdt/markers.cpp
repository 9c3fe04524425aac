#include "cdt/markers.h"

#include <atomic>

#include "util/run_both.h"

namespace deltri {
namespace {

// Below this many edge slots a second thread costs more than it saves.
constexpr std::size_t kParallelMarkerSlots = std::size_t{1} << 20;

// Marks 1 the ends of the boundary edges among slots [from, to) whose marker is still 0. The two
// halves of the slots can be done at once: both only ever turn a 0 into a 1, so the result is the
// same in any order, and the markers are accessed atomically (plain moves on common hardware)
// because a vertex can end edges in both halves. Links first: nearly every edge has a twin, so the
// corners are read only at the boundary and at dead slots, half the memory traffic of this pass
// over every edge.
void mark_boundary_ends(Mesh& mesh, EdgeRef from, EdgeRef to) {
  for (EdgeRef e = from; e < to; ++e) {
    if (mesh.link[e] != kNone || mesh.corner[e] == kNone) continue;
    for (const VertexId v : {mesh.org(e), mesh.dest(e)}) {
      std::atomic_ref<int> marker(mesh.marker[v]);
      if (marker.load(std::memory_order_relaxed) == 0) marker.store(1, std::memory_order_relaxed);
    }
  }
}

}  // namespace

void assign_boundary_markers(Mesh& mesh, bool input_had_markers, int threads) {
  const std::size_t n = mesh.vertex_count();
  if (!input_had_markers) mesh.marker.clear();
  mesh.marker.resize(n, 0);
  for (const Subsegment& s : mesh.subsegments) {
    if (s.a == kNone || s.marker == 0) continue;
    for (const VertexId v : {s.a, s.b})
      if (mesh.marker[v] == 0) mesh.marker[v] = s.marker;
  }
  const EdgeRef edges{static_cast<std::uint32_t>(mesh.corner.size())};
  run_halves(threads >= 2 && edges >= kParallelMarkerSlots, EdgeRef{0}, edges,
             [&](EdgeRef from, EdgeRef to, int) { mark_boundary_ends(mesh, from, to); });
}

}  // namespace deltri
