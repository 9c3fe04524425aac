// Undo of insert_vertex: exact inverse flips, then the inverse of whichever split was made.
#include "mesh/undo.h"

#include "mesh/internal.h"

namespace deltri {
namespace {

// The split is recognised by the fan around v it left: a triangle split makes a closed fan of
// three, an edge split a closed fan of four or (on the boundary) an open fan of two.
bool was_triangle_split(const Mesh& m, EdgeRef out) {
  unsigned count = 0;
  EdgeRef e = out;
  do {
    ++count;
    e = m.link[lprev(e)];
  } while (e != kNone && e != out && count < 4);
  return e == out && count == 3;
}

}  // namespace

void undo_insertion(Mesh& mesh, VertexId v, EdgeRef inserted, const std::vector<EdgeRef>& flipped) {
  for (auto it = flipped.rbegin(); it != flipped.rend(); ++it) detail::unflip(mesh, *it);
  const TriangleId t = triangle_of(inserted);
  const unsigned side = detail::corner_index(mesh, t, v);
  if (was_triangle_split(mesh, 3 * t + side))
    detail::unsplit_triangle(mesh, t);
  else
    detail::unsplit_edge(mesh, t, side);
}

}  // namespace deltri
