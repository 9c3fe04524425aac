// The one edge flip. Both layouts below are the same code: the two new triangles are written by
// place(), which differs only in which slot takes which triangle and where each triangle starts.
#include "mesh/internal.h"
#include "mesh/operations.h"
#include "mesh/topology_writer.h"
#include "util/invariant.h"

namespace deltri {
namespace {

// Writes triangle (x0, x1, x2) into the triangle of edge `at`, x0 at the side `shift` steps
// (lnext) past `at`. Its edge x0->x1 is the new diagonal, bonded later; edges x1->x2 and x2->x0 get
// the saved surroundings s1 and s2. Returns the side of the diagonal.
template <unsigned shift>
EdgeRef place(Mesh& m, EdgeRef at, VertexId x0, VertexId x1, VertexId x2, detail::EdgeSurround s1,
              detail::EdgeSurround s2) {
  const EdgeRef side0 = shift == 0 ? at : shift == 1 ? lnext(at) : lprev(at);
  const EdgeRef side1 = lnext(side0), side2 = lprev(side0);
  detail::corner_slots(m)[side0] = x0;
  detail::corner_slots(m)[side1] = x1;
  detail::corner_slots(m)[side2] = x2;
  detail::attach(m, side1, s1);
  detail::attach(m, side2, s2);
  return side0;
}

}  // namespace

// Before: t = (a, b, c) at sides (e, e1, e2), u = (b, a, d) at sides (f, f1, f2). The new
// triangles are T = (c, d, b) and U = (d, c, a), with the diagonal c->d first in T and d->c in U.
template <FlipLayout layout>
EdgeRef flip(Mesh& mesh, EdgeRef e) {
  const EdgeRef f = mesh.link[e];
  // The precondition every caller's test promises (lawson's may_flip, Sloan's crossed edges, the
  // ears of a deleted vertex): an interior edge, and no subsegment, which the flip would lose.
  DELTRI_ASSERT(f != kNone && mesh.link[f] == e);
  DELTRI_ASSERT(!detail::carries_subsegment(mesh, e));
  const EdgeRef e1 = lnext(e), e2 = lprev(e), f1 = lnext(f), f2 = lprev(f);
  const VertexId a = mesh.corner[e], b = mesh.corner[e1], c = mesh.corner[e2], d = mesh.corner[f2];
  const detail::EdgeSurround bc = detail::surround_of(mesh, e1), ca = detail::surround_of(mesh, e2);
  const detail::EdgeSurround ad = detail::surround_of(mesh, f1), db = detail::surround_of(mesh, f2);
  // Turn: T's c at e, U's d at f.  KeepOrigins: U's a at e (so d at lnext(e)), T's b at f.
  constexpr unsigned shift = layout == FlipLayout::Turn ? 0 : 1;
  const EdgeRef at_t = layout == FlipLayout::Turn ? e : f, at_u = layout == FlipLayout::Turn ? f : e;
  const EdgeRef cd = place<shift>(mesh, at_t, c, d, b, db, bc);
  const EdgeRef dc = place<shift>(mesh, at_u, d, c, a, ca, ad);
  detail::bond_inner(mesh, cd, dc);
  return cd;
}

template EdgeRef flip<FlipLayout::Turn>(Mesh&, EdgeRef);
template EdgeRef flip<FlipLayout::KeepOrigins>(Mesh&, EdgeRef);

}  // namespace deltri
