// Splitting a triangle or an edge at a new vertex, and the exact inverses used by undo. The
// original slots keep their place and most of their corners (only one corner becomes the new
// vertex), which is what lets the inverses find and restore them.
#include "mesh/internal.h"
#include "mesh/operations.h"

namespace deltri {

// t = (a, b, c) becomes t = (a, b, v) plus n1 = (v, b, c) and n2 = (v, c, a).
EdgeRef split_triangle(Mesh& mesh, EdgeRef e, VertexId v) {
  const TriangleId t = triangle_of(e);
  const EdgeRef t0 = 3 * t;
  const VertexId a = mesh.corner[t0], b = mesh.corner[t0 + 1], c = mesh.corner[t0 + 2];
  const detail::EdgeSurround bc = detail::surround_of(mesh, t0 + 1);
  const detail::EdgeSurround ca = detail::surround_of(mesh, t0 + 2);
  const TriangleId n1 = mesh.add_triangle(v, b, c);
  const TriangleId n2 = mesh.add_triangle(v, c, a);
  detail::copy_triangle_data(mesh, t, n1);
  detail::copy_triangle_data(mesh, t, n2);
  mesh.corner[t0 + 2] = v;
  detail::attach(mesh, 3 * n1 + 1, bc);
  detail::attach(mesh, 3 * n2 + 1, ca);
  detail::bond_inner(mesh, t0 + 1, 3 * n1);
  detail::bond_inner(mesh, t0 + 2, 3 * n2 + 2);
  detail::bond_inner(mesh, 3 * n1 + 2, 3 * n2);
  return t0 + 2;
}

// e = a->b in t = (a, b, c), twin f in u = (b, a, d). Afterwards t = (a, v, c), n1 = (v, b, c),
// u = (b, v, d), n2 = (v, a, d), with t and u keeping their sides. A subsegment on e keeps its
// record for the half at its own first endpoint; the other half gets a new record.
EdgeRef split_edge(Mesh& mesh, EdgeRef e, VertexId v) {
  const TriangleId t = triangle_of(e);
  const EdgeRef f = mesh.link[e];
  const VertexId b = mesh.dest(e), c = mesh.apex(e);
  const SubsegmentId seg = mesh.subseg.empty() ? kNone : mesh.subseg[e];
  const detail::EdgeSurround bc = detail::surround_of(mesh, lnext(e));
  const TriangleId n1 = mesh.add_triangle(v, b, c);
  detail::copy_triangle_data(mesh, t, n1);
  mesh.corner[lnext(e)] = v;
  detail::attach(mesh, 3 * n1 + 1, bc);
  detail::bond_inner(mesh, lnext(e), 3 * n1 + 2);
  if (f != kNone) {
    const TriangleId u = triangle_of(f);
    const VertexId a = mesh.org(e), d = mesh.apex(f);
    const detail::EdgeSurround ad = detail::surround_of(mesh, lnext(f));
    const TriangleId n2 = mesh.add_triangle(v, a, d);
    detail::copy_triangle_data(mesh, u, n2);
    mesh.corner[lnext(f)] = v;
    detail::attach(mesh, 3 * n2 + 1, ad);
    detail::bond_inner(mesh, lnext(f), 3 * n2 + 2);
    detail::bond_inner(mesh, e, 3 * n2);
    detail::bond_inner(mesh, 3 * n1, f);
  }
  if (seg != kNone) {
    const Subsegment old = mesh.subsegments[seg];
    const SubsegmentId fresh = static_cast<SubsegmentId>(mesh.subsegments.size());
    mesh.subsegments.push_back({v, old.b, old.marker, old.segment});
    mesh.subsegments[seg].b = v;
    const bool first_half_at_a = old.a == mesh.org(e);
    mesh.set_subsegment(e, first_half_at_a ? seg : fresh);
    mesh.set_subsegment(3 * n1, first_half_at_a ? fresh : seg);
  }
  return lnext(e);
}

namespace detail {

void unsplit_triangle(Mesh& m, TriangleId t) {
  const EdgeRef t0 = 3 * t;
  const TriangleId n1 = triangle_of(m.link[t0 + 1]), n2 = triangle_of(m.link[t0 + 2]);
  const EdgeSurround bc = surround_of(m, 3 * n1 + 1), ca = surround_of(m, 3 * n2 + 1);
  m.corner[t0 + 2] = m.corner[3 * n1 + 2];
  attach(m, t0 + 1, bc);
  attach(m, t0 + 2, ca);
  release(m, n1);
  release(m, n2);
}

// Gives the subsegment halves on both sides of v back to the record that existed before the split
// and drops the newer record when it is the last one (records are only ever appended).
SubsegmentId merge_subsegment(Mesh& m, SubsegmentId h1, SubsegmentId h2) {
  if (h1 == kNone) return kNone;
  const SubsegmentId keep = h1 < h2 ? h1 : h2, drop = h1 < h2 ? h2 : h1;
  m.subsegments[keep].b = m.subsegments[drop].b;
  if (drop + 1 == m.subsegments.size()) m.subsegments.pop_back();
  return keep;
}

void unsplit_edge(Mesh& m, TriangleId t, unsigned vertex_side) {
  const EdgeRef out = 3 * t + vertex_side;  // v->c
  const EdgeRef e = lprev(out);              // a->v
  const TriangleId n1 = triangle_of(m.link[out]);
  const EdgeRef f = m.link[3 * n1];          // b->v in u, if any
  const SubsegmentId seg =
      m.subseg.empty() ? kNone : merge_subsegment(m, m.subseg[e], m.subseg[3 * n1]);
  const EdgeSurround bc = surround_of(m, 3 * n1 + 1);
  m.corner[out] = m.corner[3 * n1 + 1];
  attach(m, out, bc);
  release(m, n1);
  if (f != kNone) {
    const TriangleId n2 = triangle_of(m.link[e]);
    const EdgeSurround ad = surround_of(m, 3 * n2 + 1);
    m.corner[lnext(f)] = m.corner[e];
    attach(m, lnext(f), ad);
    release(m, n2);
    m.bond(e, f);
  } else {
    m.link[e] = kNone;
  }
  if (!m.subseg.empty()) m.set_subsegment(e, seg);
}

}  // namespace detail
}  // namespace deltri
