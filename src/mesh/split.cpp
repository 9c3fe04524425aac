// Splitting a triangle or an edge at a new vertex. The original slots keep their place and most of
// their corners (only one corner becomes the new vertex).
#include "mesh/internal.h"
#include "mesh/operations.h"
#include "mesh/topology_writer.h"

namespace deltri {

// t = (a, b, c) becomes t = (a, b, v) plus n1 = (v, b, c) and n2 = (v, c, a), each new triangle's
// corners rotated by the layout: logical side k of n sits at slot side (k + shift) % 3.
template <SplitLayout layout>
EdgeRef split_triangle(Mesh& mesh, EdgeRef e, VertexId v) {
  constexpr unsigned shift = layout == SplitLayout::VertexFirst ? 0 : 2;
  const auto side = [](TriangleId n, unsigned logical) { return edge_of(n, (logical + shift) % 3); };
  const TriangleId t = triangle_of(e);
  const EdgeRef t0 = edge_of(t, 0), t1 = edge_of(t, 1), t2 = edge_of(t, 2);
  const VertexId a = mesh.corner[t0], b = mesh.corner[t1], c = mesh.corner[t2];
  const detail::EdgeSurround bc = detail::surround_of(mesh, t1);
  const detail::EdgeSurround ca = detail::surround_of(mesh, t2);
  const TriangleId n1 = layout == SplitLayout::VertexFirst ? mesh.add_triangle(v, b, c) : mesh.add_triangle(b, c, v);
  const TriangleId n2 = layout == SplitLayout::VertexFirst ? mesh.add_triangle(v, c, a) : mesh.add_triangle(c, a, v);
  detail::copy_triangle_data(mesh, t, n1);
  detail::copy_triangle_data(mesh, t, n2);
  detail::corner_slots(mesh)[t2] = v;
  detail::attach(mesh, side(n1, 1), bc);
  detail::attach(mesh, side(n2, 1), ca);
  detail::bond_inner(mesh, t1, side(n1, 0));
  detail::bond_inner(mesh, t2, side(n2, 2));
  detail::bond_inner(mesh, side(n1, 2), side(n2, 0));
  return t2;
}

template EdgeRef split_triangle<SplitLayout::VertexFirst>(Mesh&, EdgeRef, VertexId);
template EdgeRef split_triangle<SplitLayout::VertexLast>(Mesh&, EdgeRef, VertexId);

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
  detail::corner_slots(mesh)[lnext(e)] = v;
  detail::attach(mesh, edge_of(n1, 1), bc);
  detail::bond_inner(mesh, lnext(e), edge_of(n1, 2));
  if (f != kNone) {
    const TriangleId u = triangle_of(f);
    const VertexId a = mesh.org(e), d = mesh.apex(f);
    const detail::EdgeSurround ad = detail::surround_of(mesh, lnext(f));
    const TriangleId n2 = mesh.add_triangle(v, a, d);
    detail::copy_triangle_data(mesh, u, n2);
    detail::corner_slots(mesh)[lnext(f)] = v;
    detail::attach(mesh, edge_of(n2, 1), ad);
    detail::bond_inner(mesh, lnext(f), edge_of(n2, 2));
    detail::bond_inner(mesh, e, edge_of(n2, 0));
    detail::bond_inner(mesh, edge_of(n1, 0), f);
  }
  if (seg != kNone) {
    const Subsegment old = mesh.subsegments[seg];
    const SubsegmentId fresh = static_cast<SubsegmentId>(mesh.subsegments.size());
    mesh.subsegments.push_back({v, old.b, old.marker, old.segment});
    mesh.subsegments[seg].b = v;
    const bool first_half_at_a = old.a == mesh.org(e);
    mesh.set_subsegment(e, first_half_at_a ? seg : fresh);
    mesh.set_subsegment(edge_of(n1, 0), first_half_at_a ? fresh : seg);
  }
  return lnext(e);
}

}  // namespace deltri
