// Vertex insertion: locate, split, then Lawson flips until every edge around the new vertex is
// locally Delaunay again. Ghost triangles (corner kGhostVertex) are understood, so the same code
// grows a convex hull during incremental construction.

#include "mesh/internal.h"
#include "mesh/lawson.h"
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

EdgeRef leaving(const Mesh& m, TriangleId t, VertexId v) {
  return edge_of(t, detail::corner_index(m, t, v));
}

// Locates v and splits what it falls in (Inserted: an edge leaving v, no flips yet), or says why
// nothing was changed, as insert_vertex does.
InsertResult split_at(Mesh& mesh, Predicates& pred, VertexId v, EdgeRef hint, bool split_subsegments) {
  const Location loc = locate(mesh, pred, mesh.point(v), hint);
  switch (loc.status) {
    case LocateStatus::OnVertex:
      return {InsertStatus::Duplicate, loc.edge};
    case LocateStatus::Outside:
      // Only a hull edge with a ghost behind it lets the mesh grow outwards.
      if (loc.edge == kNone || mesh.link[loc.edge] == kNone)
        return {InsertStatus::Outside, loc.edge};
      return {InsertStatus::Inserted, split_triangle(mesh, mesh.link[loc.edge], v)};
    case LocateStatus::OnEdge:
      if (!split_subsegments && detail::carries_subsegment(mesh, loc.edge))
        return {InsertStatus::OnSubsegment, loc.edge};
      return {InsertStatus::Inserted, split_edge(mesh, loc.edge, v)};
    case LocateStatus::InTriangle:
      break;
  }
  return {InsertStatus::Inserted, split_triangle(mesh, loc.edge, v)};
}

}  // namespace

InsertResult insert_vertex(Mesh& mesh, Predicates& pred, VertexId v, EdgeRef hint,
                           bool split_subsegments) {
  const InsertResult split = split_at(mesh, pred, v, hint, split_subsegments);
  if (split.status != InsertStatus::Inserted) return split;
  flip_link(mesh, v, split.edge, [&](EdgeRef e) { return must_flip(mesh, pred, e, v); });
  // Flips keep v in the slot that was split.
  return {InsertStatus::Inserted, leaving(mesh, triangle_of(split.edge), v)};
}

InsertResult insert_vertex_into_cavity(Mesh& mesh, Predicates& pred, VertexId v, EdgeRef container,
                                       bool strictly_inside, const KnownCavity& cavity) {
  if (strictly_inside)
    if (const EdgeRef out = detail::fill_star(mesh, pred, v, cavity); out != kNone)
      return {InsertStatus::Inserted, out};
  const InsertResult split = split_at(mesh, pred, v, container, false);
  if (split.status != InsertStatus::Inserted) return split;
  // The triangle beyond a link edge never holds v, so its slot still names an original triangle.
  flip_link(mesh, v, split.edge, [&](EdgeRef e) {
    const EdgeRef f = mesh.link[e];
    return f != kNone && !detail::carries_subsegment(mesh, e) && cavity.contains(triangle_of(f));
  });
  return {InsertStatus::Inserted, leaving(mesh, triangle_of(split.edge), v)};
}

}  // namespace deltri
