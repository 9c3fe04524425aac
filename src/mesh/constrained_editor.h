// The kernel's editor for the constrained Delaunay stage: the vertex insertions and flips that
// segment insertion needs, keeping the vertex-to-edge index exact (every vertex of a rewritten
// triangle is re-pointed at an edge of that triangle), so the segment walks can start at any
// vertex without a search.
//
// Its slots differ from vertex insertion's (the output numbers triangles and corners by slot, and
// the constrained stage has always had these): flips in the KeepOrigins layout, triangle splits in
// the VertexLast layout (mesh/operations.h), and its own Lawson stack order. Its Lawson passes are
// the kernel's one routine (mesh/lawson.h).
//
// Invariants: every edit leaves a valid mesh (mesh.h) whose index is exact; the insertions and
// legalize_from end constrained Delaunay when the mesh was constrained Delaunay before (apart
// from the removed subsegment, for legalize_from); no edit flips an edge carrying a subsegment.
#pragma once

#include <vector>

#include "geometry/predicates.h"
#include "mesh/lawson.h"
#include "mesh/mesh.h"
#include "mesh/vertex_edges.h"

namespace deltri {

class ConstrainedEditor {
 public:
  Mesh& mesh;
  Predicates& pred;

  ConstrainedEditor(Mesh& m, Predicates& p) : mesh(m), pred(p), index_(m) {}

  // An edge leaving v, kNone if v is in no triangle (an exact lookup).
  EdgeRef leaving(VertexId v) const { return index_.known(v); }
  // An edge between a and b (a->b whenever that side has a triangle), or kNone.
  EdgeRef find(VertexId a, VertexId b) { return index_.find(mesh, a, b); }

  // The kernel's flip in its KeepOrigins layout: for e = (p, q) with apexes r (left) and s
  // (right), slot e holds p->s, slot link(e) holds q->r, and the new diagonal s->r, r->s sits at
  // lnext of each, so callers know where every edge went. Flipping e or its twin is the same edit.
  void flip(EdgeRef e);
  // Whether flipping e gives two strictly counter-clockwise triangles.
  bool flippable(EdgeRef e);
  // Whether e, with a triangle on each side, fails the empty-circle test (exact, strict).
  bool violates_delaunay(EdgeRef e);
  // Whether Lawson may flip e: a twin, no subsegment, not locally Delaunay.
  bool may_flip(EdgeRef e);

  // Splits the triangle of e at the new vertex v strictly inside it, then restores the
  // constrained Delaunay property by flips that never cross a subsegment.
  void insert_in_triangle(EdgeRef e, VertexId v);
  // Same for v on the relative interior of edge e, which must carry no subsegment.
  void insert_on_edge(EdgeRef e, VertexId v);
  // Lawson flips starting from edge e, which may have stopped being locally Delaunay (its
  // subsegment was just removed); afterwards the triangulation is constrained Delaunay again.
  void legalize_from(EdgeRef e);
  // Lawson flips from every edge leaving v, spreading to every edge a flip touches: after an
  // insertion on an edge whose subsegment was just removed (the mesh was constrained Delaunay only
  // with it, so the insertion's own flips, confined to v's link, do not suffice: the halves and
  // the other edges at v need not be locally Delaunay); afterwards it is constrained Delaunay again.
  void legalize_star(VertexId v);
  // Lawson flips from `stack`, spreading to every edge a flip touches, of the edges that pass
  // the caller's test (which must imply may_flip; segment recovery confines it to its cavity).
  template <class MayFlip>
  void legalize(std::vector<EdgeRef>& stack, MayFlip&& test) {
    lawson<FlipLayout::KeepOrigins, LawsonScope::Everywhere>(mesh, stack, kNone, test,
                                                             [this](EdgeRef e, EdgeRef f) { flipped(e, f); });
  }

 private:
  void touch(TriangleId t) { index_.touch(mesh, t); }
  // After a flip of e and its old twin f: both triangles were rewritten.
  void flipped(EdgeRef e, EdgeRef f) {
    touch(triangle_of(e));
    touch(triangle_of(f));
  }
  // Lawson flips from the given edges, each opposite the new vertex v in its triangle.
  void legalize_link(std::vector<EdgeRef>& stack, VertexId v);

  VertexEdges index_;
};

}  // namespace deltri
