// Finding the current edge between two vertices. Flips rewrite triangle slots, so an edge
// reference remembered in a queue can go stale while the edge itself survives; the finder keeps
// one edge leaving each vertex (refreshed whenever refinement looks at a vertex's star) and
// turns around it. A stale hint is repaired by a short search of nearby slots, and in the last
// resort by a scan of the whole mesh.
#pragma once

#include <vector>

#include "mesh/mesh.h"

namespace deltri {

class EdgeFinder {
 public:
  explicit EdgeFinder(const Mesh& mesh);
  // Records that e leaves org(e).
  void note(const Mesh& mesh, EdgeRef e);
  // Records every edge of the triangles around the vertex that `out` leaves.
  void note_star(const Mesh& mesh, EdgeRef out);
  // An edge between a and b (from a to b whenever that side has a triangle), or kNone if a and b
  // are not adjacent.
  EdgeRef find(const Mesh& mesh, VertexId a, VertexId b);
  // An edge leaving v, or kNone if v is in no triangle.
  EdgeRef leaving(const Mesh& mesh, VertexId v);

 private:
  std::vector<EdgeRef> out_;
};

// Calls visit(e) for an edge e leaving v in every triangle around v, turning counter-clockwise
// from `out` and, if the boundary interrupts the turn, clockwise from `out` too.
template <class Visit>
void for_each_around(const Mesh& mesh, EdgeRef out, Visit&& visit) {
  EdgeRef e = out;
  do {
    visit(e);
    e = mesh.link[lprev(e)];
  } while (e != kNone && e != out);
  if (e == out) return;
  for (EdgeRef twin = mesh.link[out]; twin != kNone; twin = mesh.link[e]) {
    e = lnext(twin);
    visit(e);
  }
}

}  // namespace deltri
