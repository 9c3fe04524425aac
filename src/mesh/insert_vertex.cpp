// Vertex insertion: locate, split, then Lawson flips until every edge around the new vertex is
// locally Delaunay again. Ghost triangles (corner kGhostVertex) are understood, so the same code
// grows a convex hull during incremental construction.
#include <vector>

#include "mesh/internal.h"
#include "mesh/operations.h"

namespace deltri {
namespace {

// Whether edge e, seen from its triangle whose apex is the new vertex v, must be flipped. The
// circle of a ghost triangle is the open half-plane beyond its real edge, which lets flips widen
// the hull; a point merely collinear with a hull edge never flips it (the triangle would be flat).
bool must_flip(const Mesh& m, Predicates& pred, EdgeRef e, VertexId v) {
  const EdgeRef f = m.link[e];
  if (f == kNone || detail::carries_subsegment(m, e)) return false;
  const VertexId a = m.org(e), b = m.dest(e), d = m.apex(f);
  const Point& p = m.point(v);
  if (a == kGhostVertex) return pred.orient2d(m.point(d), m.point(b), p) > 0;
  if (b == kGhostVertex) return pred.orient2d(m.point(a), m.point(d), p) > 0;
  if (d == kGhostVertex) return false;  // p is inside the hull, on the real side of edge b->a
  return pred.incircle(m.point(b), m.point(a), m.point(d), p) > 0;
}

// The edges opposite v in every triangle around it (the fan may be open at the boundary).
void push_link_of(const Mesh& m, EdgeRef out, std::vector<EdgeRef>& stack) {
  EdgeRef e = out;
  do {
    stack.push_back(lnext(e));
    e = m.link[lprev(e)];
  } while (e != kNone && e != out);
  if (e == out) return;
  for (EdgeRef s = m.link[out]; s != kNone; s = m.link[e]) {
    e = lnext(s);
    stack.push_back(lnext(e));
  }
}

void restore_delaunay(Mesh& m, Predicates& pred, VertexId v, EdgeRef out,
                      std::vector<EdgeRef>* flipped) {
  std::vector<EdgeRef> stack;
  push_link_of(m, out, stack);
  while (!stack.empty()) {
    const EdgeRef e = stack.back();
    stack.pop_back();
    if (m.apex(e) != v || !must_flip(m, pred, e, v)) continue;
    const EdgeRef f = m.link[e];
    const EdgeRef g = flip(m, e);  // v -> old apex of f; the link of v is now lnext(g), lprev(f)
    if (flipped) flipped->push_back(g);
    stack.push_back(lnext(g));
    stack.push_back(lprev(f));
  }
}

EdgeRef leaving(const Mesh& m, TriangleId t, VertexId v) {
  return 3 * t + detail::corner_index(m, t, v);
}

}  // namespace

InsertResult insert_vertex(Mesh& mesh, Predicates& pred, VertexId v, EdgeRef hint,
                           bool split_subsegments, std::vector<EdgeRef>* flipped) {
  const Location loc = locate(mesh, pred, mesh.point(v), hint);
  EdgeRef out = kNone;
  switch (loc.status) {
    case LocateStatus::OnVertex:
      return {InsertStatus::Duplicate, loc.edge};
    case LocateStatus::Outside:
      // Only a hull edge with a ghost behind it lets the mesh grow outwards.
      if (loc.edge == kNone || mesh.link[loc.edge] == kNone)
        return {InsertStatus::Outside, loc.edge};
      out = split_triangle(mesh, mesh.link[loc.edge], v);
      break;
    case LocateStatus::OnEdge:
      if (!split_subsegments && detail::carries_subsegment(mesh, loc.edge))
        return {InsertStatus::OnSubsegment, loc.edge};
      out = split_edge(mesh, loc.edge, v);
      break;
    case LocateStatus::InTriangle:
      out = split_triangle(mesh, loc.edge, v);
      break;
  }
  restore_delaunay(mesh, pred, v, out, flipped);
  // Flips keep v in the slot that was split (undo_insertion relies on this edge being there).
  return {InsertStatus::Inserted, leaving(mesh, triangle_of(out), v)};
}

}  // namespace deltri
