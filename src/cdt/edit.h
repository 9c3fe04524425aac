// Topology edits used by the constrained Delaunay stage. They keep a vertex -> edge map valid
// (every vertex of a touched triangle is re-pointed at an edge of that triangle), which the
// mesh-level operations know nothing about; that is why the stage has its own small editor.
#pragma once

#include <vector>

#include "geometry/predicates.h"
#include "mesh/mesh.h"

namespace deltri {

struct CdtEditor {
  Mesh& mesh;
  Predicates& pred;
  std::vector<EdgeRef> vertex_edge;  // an edge leaving each vertex, kNone if it is in no triangle

  CdtEditor(Mesh& m, Predicates& p);

  // Points the corners of t at t's edges.
  void touch(TriangleId t);
  // Makes sure a (new) vertex has a slot in the map.
  void grow_to_vertices();

  // The kernel's flip in its KeepOrigins layout (mesh/operations.h): for e = (p, q) with apexes r
  // (left) and s (right), slot e holds p->s, slot link(e) holds q->r and the new diagonal s->r,
  // r->s sits at lnext of each, so the callers know where every edge went. Then the map is updated.
  void flip(EdgeRef e);
  // Whether flipping e gives two strictly counter-clockwise triangles.
  bool flippable(EdgeRef e);
  // Whether e, with a triangle on each side, fails the empty-circle test (exact, strict).
  bool violates_delaunay(EdgeRef e);

  // Splits the triangle of e at the new vertex v strictly inside it, then restores the
  // constrained Delaunay property by flips that never cross a subsegment.
  void insert_in_triangle(EdgeRef e, VertexId v);
  // Same for v on the relative interior of edge e, which must carry no subsegment.
  void insert_on_edge(EdgeRef e, VertexId v);
  // Lawson flips starting from edge e, which may have stopped being locally Delaunay (its
  // subsegment was just removed); afterwards the triangulation is constrained Delaunay again.
  void legalize_from(EdgeRef e);

 private:
  // Lawson flips from the given edges, each opposite the new vertex v in its triangle.
  void legalize(std::vector<EdgeRef>& stack);
};

}  // namespace deltri
