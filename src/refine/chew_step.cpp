// Fig. 39 l.40-43, Chew's step: the free vertices inside the diametral circle of a subsegment s
// that the two triangles beside s can see (a search that never crosses a subsegment) are deleted
// before s is split, so that with lenses no vertex is left closer to the new subsegments than
// their diametral circles allow.
#include <algorithm>
#include <vector>

#include "geometry/encroachment.h"
#include "mesh/delete_vertex.h"
#include "refine/terminator.h"

namespace deltri {
namespace {

// The edge a->b among the triangles `created`, or kNone.
EdgeRef edge_among(const Mesh& mesh, const std::vector<TriangleId>& created, VertexId a, VertexId b) {
  EdgeRef found = kNone;
  for (TriangleId t : created)
    for (unsigned i = 0; i < 3; ++i)
      if (mesh.org(edge_of(t, i)) == a && mesh.dest(edge_of(t, i)) == b) found = edge_of(t, i);
  return found;
}

}  // namespace

// The free vertices strictly inside s's diametral circle that the triangles beside s can see: a
// search from them that goes on only through edges with an end inside the circle (the circle is
// convex, so the triangles reached cover everything in it that the start can see), at most
// kDeletionSearchLimit triangles.
std::vector<VertexId> Terminator::free_vertices_seen_from(EdgeRef s) {
  const VertexId a = mesh_.org(s), b = mesh_.dest(s);
  const Point& pa = mesh_.point(a);
  const Point& pb = mesh_.point(b);
  const auto inside = [&](VertexId w) {
    return w != a && w != b && strictly_inside_diametral_circle(pa, pb, mesh_.point(w));
  };
  marks_.begin();
  std::vector<TriangleId> todo{triangle_of(s)};
  marks_.mark(todo[0]);
  if (mesh_.link[s] != kNone && marks_.mark(triangle_of(mesh_.link[s]))) todo.push_back(triangle_of(mesh_.link[s]));
  std::vector<VertexId> doomed;
  for (std::size_t k = 0; k < todo.size() && k < kDeletionSearchLimit; ++k) {
    for (unsigned i = 0; i < 3; ++i) {
      const EdgeRef e = edge_of(todo[k], i);
      const VertexId w = mesh_.org(e);
      const bool w_inside = inside(w);
      if (w_inside && mesh_.kind[w] == VertexKind::Free && std::find(doomed.begin(), doomed.end(), w) == doomed.end())
        doomed.push_back(w);
      const EdgeRef twin = mesh_.link[e];
      if (twin == kNone || mesh_.subseg[e] != kNone) continue;
      if ((w_inside || inside(mesh_.dest(e))) && marks_.mark(triangle_of(twin))) todo.push_back(triangle_of(twin));
    }
  }
  return doomed;
}

// Returns the edge that now carries s (deletions rewrite slots), or kNone.
EdgeRef Terminator::delete_free_vertices_near(EdgeRef s, bool queue_triangles) {
  const VertexId a = mesh_.org(s), b = mesh_.dest(s);
  std::vector<TriangleId> created;
  for (VertexId w : free_vertices_seen_from(s)) {  // l.40
    const EdgeRef out = finder_.leaving(mesh_, w);
    created.clear();
    if (out == kNone || !delete_vertex(mesh_, pred_, out, created)) continue;
    ++report_.vertices_deleted;
    // s moves only when w was the apex beside it, and then into one of the new triangles (a
    // finder could miss it at a vertex where two fans touch).
    if (!mesh_.is_live(triangle_of(s)) || mesh_.org(s) != a || mesh_.dest(s) != b) {
      s = edge_among(mesh_, created, a, b);
      if (s == kNone) return kNone;  // cannot happen: the star's link keeps its edges
    }
    for (TriangleId t : created) {  // l.41
      for (unsigned i = 0; i < 3; ++i) finder_.note(mesh_, edge_of(t, i));
      if (queue_triangles) enqueue_if_bad(t);  // l.42-43
    }
  }
  return s;
}

}  // namespace deltri
