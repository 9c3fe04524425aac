// The kernel's one vertex-to-edge index: an edge leaving each vertex, so that a vertex's star and
// the edge between two vertices are found without a search. Flips and splits rewrite slots, so a
// remembered edge can go stale while the vertex survives. Two ways to keep it:
//   * exact: the caller touches every triangle an edit rewrote (the constrained editor does, so
//     every lookup is a hit);
//   * lazy: the caller notes the stars it looks at (refinement does); a stale entry is repaired
//     by a short search of nearby slots, and in the last resort by a scan of the whole mesh.
// leaving() and find() are correct either way; only their cost differs.
#pragma once

#include <vector>

#include "mesh/mesh.h"

namespace deltri {

class VertexEdges {
 public:
  // Every vertex of a live triangle gets its last edge in slot order.
  explicit VertexEdges(const Mesh& mesh);
  // Records that e leaves org(e). Inline: a flip notes six edges, an insertion its whole star.
  void note(const Mesh& mesh, EdgeRef e) {
    const VertexId v = mesh.org(e);
    if (v >= out_.size()) [[unlikely]]
      grow_to(mesh, v);
    out_[v] = e;
  }
  // Records the three edges of triangle t (after an edit rewrote it).
  void touch(const Mesh& mesh, TriangleId t) {
    for (unsigned i = 0; i < 3; ++i) note(mesh, edge_of(t, i));
  }
  // Records every edge of the triangles around the vertex that `out` leaves.
  void note_star(const Mesh& mesh, EdgeRef out);
  // An edge between a and b (from a to b whenever that side has a triangle), or kNone if a and b
  // are not adjacent.
  EdgeRef find(const Mesh& mesh, VertexId a, VertexId b);
  // An edge leaving v, or kNone if v is in no triangle.
  EdgeRef leaving(const Mesh& mesh, VertexId v);
  // The recorded entry for v, unchecked: an edge leaving v when the index is kept exact.
  EdgeRef known(VertexId v) const { return v < out_.size() ? out_[v] : kNone; }

 private:
  void grow_to(const Mesh& mesh, VertexId v);
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
