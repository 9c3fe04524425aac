// Fig. 39 l.40-43, Chew's step: the free vertices inside the diametral circle of a subsegment s
// that the two triangles beside s can see (a search that never crosses a subsegment) and that the
// split point p would come too close to (too_close_to_split) are deleted before s is split at p, so
// that with lenses no short edge appears at p.
#include <algorithm>
#include <cmath>
#include <vector>

#include "geometry/constructions.h"
#include "geometry/encroachment.h"
#include "mesh/delete_vertex.h"
#include "mesh/vertex_edges.h"
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

// Whether Chew's step deletes the free vertex w, inside the diametral circle of a subsegment about
// to be split at p: when p is nearer to w than w's nearest neighbour is. Chew deletes every free
// vertex in the circle, so that p's nearest visible neighbours are the subsegment's ends and no
// short edge appears (Sec. 4.2, proof of Lemma 5). A vertex at least as far from p as from its
// nearest neighbour x makes no edge at p shorter than the edge wx it already has; deleting it only
// undid refinement that was then done again: the side of a unit plate split late, its circle
// reaching a 1e-4 wide slit in the middle, deleted 41 vertices of the slit's grading, most of them
// far from p, and they were put back as before or finer. With the rule, p's insertion radius is at
// least wx (or the paper's radius if no vertex is kept), and of w and x the younger has an
// insertion radius at most wx: Lemma 5's relation r_v >= r_p cos(theta) holds with that vertex as
// parent (with the factor 1), and no edge shorter than those already there appears, which is what
// Theorem 4's argument for termination uses. Measured in docs/refinement.md ("Chew's deletion").
// Chew's second algorithm (Sec. 4.1) deletes every one, as the paper states it.
bool Terminator::too_close_to_split(VertexId w, const Point& p) {
  if (policy_.deletes_every_free_vertex) return true;
  const Point& q = mesh_.point(w);
  const EdgeRef out = finder_.leaving(mesh_, w);
  if (out == kNone) return true;
  double nearest2 = HUGE_VAL;
  for_each_around(mesh_, out,
                  [&](EdgeRef e) { nearest2 = std::min(nearest2, squared_distance(q, mesh_.point(mesh_.dest(e)))); });
  return squared_distance(q, p) < nearest2;
}

// The free vertices strictly inside s's diametral circle that the triangles beside s can see: a
// search from them that goes on only through edges with an end inside the circle (the circle is
// convex, so the triangles reached cover everything in it that the start can see), at most
// kDeletionSearchLimit triangles.
std::vector<VertexId> Terminator::free_vertices_seen_from(EdgeRef s, const Point& p) {
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
      if (w_inside && mesh_.kind[w] == VertexKind::Free && std::find(doomed.begin(), doomed.end(), w) == doomed.end() &&
          too_close_to_split(w, p))
        doomed.push_back(w);
      const EdgeRef twin = mesh_.link[e];
      if (twin == kNone || mesh_.subseg.has(e)) continue;
      if ((w_inside || inside(mesh_.dest(e))) && marks_.mark(triangle_of(twin))) todo.push_back(triangle_of(twin));
    }
  }
  return doomed;
}

// Returns the edge that now carries s (deletions rewrite slots), or kNone.
EdgeRef Terminator::delete_free_vertices_near(EdgeRef s, const Point& p, bool queue_triangles) {
  const VertexId a = mesh_.org(s), b = mesh_.dest(s);
  std::vector<TriangleId> created;
  for (VertexId w : free_vertices_seen_from(s, p)) {  // l.40
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
