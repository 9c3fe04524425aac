#include "mesh/delete_vertex.h"

#include "mesh/internal.h"
#include "mesh/operations.h"
#include "mesh/topology_writer.h"

namespace deltri {
namespace {

// The edges leaving v counter-clockwise from out, or nothing if v is on the boundary or an edge
// at it carries a subsegment.
bool star_of(const Mesh& mesh, EdgeRef out, std::vector<EdgeRef>& spokes) {
  spokes.clear();
  EdgeRef e = out;
  do {
    if (detail::carries_subsegment(mesh, e) || detail::carries_subsegment(mesh, lprev(e))) return false;
    spokes.push_back(e);
    const EdgeRef back = mesh.link[lprev(e)];
    if (back == kNone) return false;
    e = back;
  } while (e != out && spokes.size() <= mesh.corner.size());
  return e == out && spokes.size() >= 3;
}

// Whether cutting the ear (a, b, c) off v's link by flipping v-b leaves v strictly inside the rest.
// With four link vertices, v may lie on the chord a-c itself (a circumcentre at the midpoint of a
// right triangle's hypotenuse): the flip then leaves a flat triangle (a, c, v) for a moment, and the
// merge of the last three triangles that follows at once removes it with v, leaving (a, b, c) and
// the proper triangle on the other side of a-c. Refusing that case left such vertices undeletable,
// and Chew's step (Sec. 4) split ever smaller subsegments around them.
bool ear_keeps_v_inside(Predicates& pred, const Point& a, const Point& c, const Point& v, std::size_t m) {
  const double side = pred.orient2d(a, c, v);
  return side > 0 || (side == 0 && m == 4);
}

// Picks the ears to cut, as positions in the shrinking list of link vertices; false if at some
// point no ear is both flippable and empty.
bool plan_ears(Predicates& pred, const Point& v, std::vector<Point> link, std::vector<std::size_t>& order) {
  order.clear();
  while (link.size() > 3) {
    const std::size_t m = link.size();
    std::size_t chosen = m;
    for (std::size_t i = 0; i < m && chosen == m; ++i) {
      const Point& a = link[(i + m - 1) % m];
      const Point& b = link[i];
      const Point& c = link[(i + 1) % m];
      if (pred.orient2d(a, b, c) <= 0 || !ear_keeps_v_inside(pred, a, c, v, m)) continue;
      bool empty = true;
      for (std::size_t j = 0; j < m && empty; ++j)
        if (j != i && j != (i + 1) % m && j != (i + m - 1) % m) empty = pred.incircle(a, b, c, link[j]) <= 0;
      if (empty) chosen = i;
    }
    if (chosen == m) return false;
    order.push_back(chosen);
    link.erase(link.begin() + static_cast<std::ptrdiff_t>(chosen));
  }
  return true;
}

// The last three triangles around v become one, in the slot of triangle_of(out).
TriangleId merge_last_three(Mesh& mesh, EdgeRef out) {
  const EdgeRef e0 = out, e1 = lnext(out), e2 = lprev(out);  // v->u0, u0->u1, u1->v
  const EdgeRef in_t1 = lnext(mesh.link[e2]);                 // u1->u2
  const EdgeRef in_t2 = lprev(mesh.link[e0]);                 // u2->u0
  const TriangleId t1 = triangle_of(in_t1), t2 = triangle_of(in_t2);
  const VertexId u2 = mesh.org(in_t2);
  const detail::EdgeSurround s12 = detail::surround_of(mesh, in_t1), s20 = detail::surround_of(mesh, in_t2);
  detail::corner_slots(mesh)[e0] = u2;
  detail::attach(mesh, e2, s12);
  detail::attach(mesh, e0, s20);
  detail::release(mesh, t1);
  detail::release(mesh, t2);
  return triangle_of(e1);
}

}  // namespace

bool delete_vertex(Mesh& mesh, Predicates& pred, EdgeRef out, std::vector<TriangleId>& created) {
  const VertexId v = mesh.org(out);
  std::vector<EdgeRef> spokes;
  if (!star_of(mesh, out, spokes)) return false;
  std::vector<Point> link;
  std::vector<VertexId> ids;
  for (EdgeRef e : spokes) {
    link.push_back(mesh.point(mesh.dest(e)));
    ids.push_back(mesh.dest(e));
  }
  std::vector<std::size_t> order;
  if (!plan_ears(pred, mesh.point(v), link, order)) return false;
  EdgeRef from_v = out;
  for (std::size_t position : order) {
    const VertexId u = ids[position];
    ids.erase(ids.begin() + static_cast<std::ptrdiff_t>(position));
    EdgeRef e = from_v;
    while (mesh.dest(e) != u) e = mesh.link[lprev(e)];
    // flip turns v->u into the ear's edge; the other triangle of the flip keeps v.
    const EdgeRef ear_edge = flip(mesh, e);
    created.push_back(triangle_of(ear_edge));
    from_v = lprev(mesh.link[ear_edge]);  // in the triangle (u_prev, u_next, v): v -> u_prev
  }
  created.push_back(merge_last_three(mesh, from_v));
  mesh.kind[v] = VertexKind::Dead;
  return true;
}

}  // namespace deltri
