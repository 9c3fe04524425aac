// Edge flips. The new edge takes the slot of the old edge in each triangle, and every outer edge
// keeps the triangle it bounds.
#include "mesh/internal.h"
#include "mesh/operations.h"

namespace deltri {

// Before:  t = (a, b, c) at sides (e, e1, e2), u = (b, a, d) at sides (f, f1, f2).
// After:   t = (c, d, b),                       u = (d, c, a).
// Outer edges b->c and d->b end up in t, c->a and a->d in u.
EdgeRef flip(Mesh& mesh, EdgeRef e) {
  const EdgeRef f = mesh.link[e];
  const EdgeRef e1 = lnext(e), e2 = lprev(e), f1 = lnext(f), f2 = lprev(f);
  const VertexId a = mesh.corner[e], b = mesh.corner[e1], c = mesh.corner[e2], d = mesh.corner[f2];
  const detail::EdgeSurround bc = detail::surround_of(mesh, e1), ca = detail::surround_of(mesh, e2);
  const detail::EdgeSurround ad = detail::surround_of(mesh, f1), db = detail::surround_of(mesh, f2);
  mesh.corner[e] = c;
  mesh.corner[e1] = d;
  mesh.corner[e2] = b;
  mesh.corner[f] = d;
  mesh.corner[f1] = c;
  mesh.corner[f2] = a;
  detail::attach(mesh, e1, db);
  detail::attach(mesh, e2, bc);
  detail::attach(mesh, f1, ca);
  detail::attach(mesh, f2, ad);
  detail::bond_inner(mesh, e, f);
  return e;
}

}  // namespace deltri
