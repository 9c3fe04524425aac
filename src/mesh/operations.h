// Primitive operations on a Mesh. They keep every invariant listed in mesh.h; none of them reads
// switches or prints. Geometry decisions use exact predicates only.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "geometry/predicates.h"
#include "mesh/mesh.h"

namespace deltri {

// Where a point lies relative to the mesh.
enum class LocateStatus {
  InTriangle,  // strictly inside triangle_of(edge)
  OnEdge,      // in the relative interior of edge
  OnVertex,    // at org(edge)
  Outside,     // outside the mesh; edge is a boundary edge the point is strictly right of
};
struct Location {
  LocateStatus status = LocateStatus::Outside;
  EdgeRef edge = kNone;
};

// Walks from the live triangle of `hint` towards p (visibility walk, exact orient2d). Never
// leaves the mesh and never loops: a walk that would cycle falls back to a scan.
Location locate(const Mesh& mesh, Predicates& pred, const Point& p, EdgeRef hint);

// Flips the edge e = a->b shared by t = (a, b, c) and u = (b, a, d); the quadrilateral must be
// strictly convex and e must carry no subsegment. The new triangles are (c, d, b) and (d, c, a);
// every outer edge keeps its twin and subsegment. Returns the new edge c->d. Which slot holds which
// new triangle is the layout (the output numbers triangles by slot, so each caller keeps the layout
// its stage has always had):
//   Turn         t = (c, d, b) with c->d at e's slot, u = (d, c, a) with d->c at f's slot. Used by
//                vertex insertion, deletion, the sweepline and refinement.
//   KeepOrigins  t = (a, d, c) and u = (b, c, d): each slot keeps its origin (a at e, b at f) and
//                the new edge sits at lnext of each, d->c in t and c->d in u, so the outer edges
//                are at e, lprev(e), f and lprev(f). Used by the constrained Delaunay stage.
enum class FlipLayout { Turn, KeepOrigins };
template <FlipLayout layout = FlipLayout::Turn>
EdgeRef flip(Mesh& mesh, EdgeRef e);
extern template EdgeRef flip<FlipLayout::Turn>(Mesh&, EdgeRef);
extern template EdgeRef flip<FlipLayout::KeepOrigins>(Mesh&, EdgeRef);

// Splits triangle_of(e) = (a, b, c) into three around the new vertex v (which must lie strictly
// inside): t keeps its slot as (a, b, v), and two new slots n1, n2 hold (v, b, c) and (v, c, a).
// The layout says where v sits in the new slots (the output numbers corners by slot):
//   VertexFirst  n1 = (v, b, c), n2 = (v, c, a). Used by vertex insertion and refinement.
//   VertexLast   n1 = (b, c, v), n2 = (c, a, v), so the old edges b->c and c->a sit at side 0.
//                Used by the constrained Delaunay editor.
// Returns the edge v->a in t's slot.
enum class SplitLayout { VertexFirst, VertexLast };
template <SplitLayout layout = SplitLayout::VertexFirst>
EdgeRef split_triangle(Mesh& mesh, EdgeRef e, VertexId v);
extern template EdgeRef split_triangle<SplitLayout::VertexFirst>(Mesh&, EdgeRef, VertexId);
extern template EdgeRef split_triangle<SplitLayout::VertexLast>(Mesh&, EdgeRef, VertexId);

// Splits edge e (and its twin, if any) at the new vertex v, which must lie on e's relative interior.
// A subsegment on e is split into two subsegments. Returns an edge leaving v.
EdgeRef split_edge(Mesh& mesh, EdgeRef e, VertexId v);

enum class InsertStatus {
  Inserted,     // v is now a vertex of the mesh, Delaunay restored by Lawson flips
  Duplicate,    // a vertex already sits at that point; edge.org is it, nothing changed
  OnSubsegment, // v lies on a subsegment and splitting segments was not allowed; nothing changed
  Outside,      // v lies outside the mesh; nothing changed
};
struct InsertResult {
  InsertStatus status = InsertStatus::Outside;
  EdgeRef edge = kNone;  // Inserted: an edge leaving v; Duplicate: an edge leaving the old vertex;
                         // OnSubsegment: that subsegment's edge
};

// Inserts existing vertex v (already in mesh.points) by locating it from `hint`, splitting the
// triangle or edge it falls in, and restoring the (constrained) Delaunay property with Lawson
// flips that never flip an edge carrying a subsegment. `split_subsegments` allows a vertex on a
// subsegment to split it. Where ghost triangles
// (corner kGhostVertex) cover the outside of the hull, a point beyond it is inserted and the hull
// grows; only a plain boundary edge (link kNone) makes the answer Outside.
InsertResult insert_vertex(Mesh& mesh, Predicates& pred, VertexId v, EdgeRef hint,
                           bool split_subsegments = true);

// The triangles an insertion will destroy, found beforehand (refine/candidate_probe.h): either
// the `count` slots of `list`, or (list null) the slots t < size with stamp[t] == mark. The search
// also recorded the cavity's `boundary` (its edges with the cavity on their left, whose far side
// is not in the cavity or which carry a subsegment) and its triangles with no boundary edge.
struct KnownCavity {
  // The cavity's triangles: a list, or, for a large cavity, an open-addressing hash set of
  // 2^table_bits slots (kNone = empty) probed from cavity_slot(t).
  const TriangleId* list = nullptr;
  std::size_t count = 0;
  const TriangleId* table = nullptr;
  unsigned table_bits = 0;
  std::size_t triangles = 0;
  std::span<const EdgeRef> boundary;
  std::span<const TriangleId> inner;
  bool contains(TriangleId t) const;
};

// Fibonacci hashing: the top `bits` bits of t times 2^32 / phi.
inline std::uint32_t cavity_slot(TriangleId t, unsigned bits) {
  return static_cast<std::uint32_t>((static_cast<std::uint64_t>(t) * 2654435769u & 0xFFFFFFFFu) >> (32 - bits));
}

inline bool KnownCavity::contains(TriangleId t) const {
  if (list == nullptr) {
    if (table == nullptr) return false;
    const std::uint32_t mask = (std::uint32_t{1} << table_bits) - 1;
    for (std::uint32_t i = cavity_slot(t, table_bits);; i = (i + 1) & mask) {
      if (table[i] == t) return true;
      if (table[i] == kNone) return false;
    }
  }
  for (std::size_t i = 0; i < count; ++i)
    if (list[i] == t) return true;
  return false;
}

// insert_vertex without subsegment splits, for a vertex whose cavity is already known: in a
// constrained Delaunay triangulation Lawson's flips remove exactly the triangles reachable from
// the container across non-subsegment edges whose circumcircles strictly contain v. A small
// cavity with v strictly inside `container` is replaced by the fan from v to its boundary in one
// pass (Bowyer-Watson); otherwise Lawson's flips run with each decision a lookup instead of an
// incircle test. Both give the same triangulation; the slots differ.
InsertResult insert_vertex_into_cavity(Mesh& mesh, Predicates& pred, VertexId v, EdgeRef container,
                                       bool strictly_inside, const KnownCavity& cavity);

}  // namespace deltri
