#include "cdt/walk.h"

namespace deltri {

namespace {

// Sign-exact: a floating-point difference is zero, positive or negative exactly when the exact
// one is, so comparing along the dominant non-zero axis orders collinear points exactly.
bool same_sign(double a, double b) { return (a > 0.0 && b > 0.0) || (a < 0.0 && b < 0.0); }

// Whether point w (on the ray from u through q) comes strictly before q.
bool strictly_before(const Point& u, const Point& q, const Point& w) {
  if (q.x != u.x) return q.x > u.x ? w.x < q.x : w.x > q.x;
  return q.y > u.y ? w.y < q.y : w.y > q.y;
}

// Checks the triangle of e (org u) for the ray; returns true when it decided `out`.
bool examine(const Mesh& mesh, Predicates& pred, EdgeRef e, const Point& q, RayStart& out) {
  const Point& u = mesh.point(mesh.org(e));
  const VertexId a = mesh.dest(e), b = mesh.apex(e);
  const double oa = pred.orient2d(u, q, mesh.point(a));
  if (oa == 0.0 && on_ray_side(u, q, mesh.point(a))) {
    out = {RayStart::Kind::Vertex, e, a, lnext(e)};
    return true;
  }
  if (oa < 0.0 && pred.orient2d(u, q, mesh.point(b)) > 0.0) {
    out = {RayStart::Kind::Cross, lnext(e), kNone, kNone};
    return true;
  }
  return false;
}

}  // namespace

bool on_ray_side(const Point& u, const Point& q, const Point& w) {
  if (q.x != u.x) return same_sign(w.x - u.x, q.x - u.x);
  return same_sign(w.y - u.y, q.y - u.y);
}

RayStart first_step(const Mesh& mesh, Predicates& pred, EdgeRef from_u, const Point& q) {
  RayStart out;
  // Counter-clockwise first; a vertex on the boundary has a fan, so finish clockwise.
  EdgeRef e = from_u;
  while (true) {
    if (examine(mesh, pred, e, q, out)) return out;
    const EdgeRef n = mesh.onext(e);
    if (n == from_u) return out;
    if (n == kNone) break;
    e = n;
  }
  // The counter-clockwise-most edge's apex is nobody's destination in this fan: test it too.
  const Point& u = mesh.point(mesh.org(e));
  const VertexId b = mesh.apex(e);
  if (pred.orient2d(u, q, mesh.point(b)) == 0.0 && on_ray_side(u, q, mesh.point(b)))
    return {RayStart::Kind::Vertex, lprev(e), b, lprev(e)};
  for (e = from_u; mesh.link[e] != kNone;) {
    e = lnext(mesh.link[e]);
    if (examine(mesh, pred, e, q, out)) return out;
  }
  return out;
}

// In a valid triangulation the edges at u have distinct directions and no triangle at u holds the
// direction of an edge u-v strictly inside its angle, so first_step's rotation (counter-clockwise,
// then clockwise past a boundary) stops at the edge u-v and nowhere earlier: its Vertex answer is
// this one.
RayStart first_step_to_vertex(const Mesh& mesh, Predicates& pred, EdgeRef from_u, VertexId v) {
  EdgeRef e = from_u;
  while (true) {
    if (mesh.dest(e) == v) return {RayStart::Kind::Vertex, e, v, lnext(e)};
    const EdgeRef n = mesh.onext(e);
    if (n == from_u) break;
    if (n == kNone) {
      for (e = from_u; mesh.link[e] != kNone;) {
        e = lnext(mesh.link[e]);
        if (mesh.dest(e) == v) return {RayStart::Kind::Vertex, e, v, lnext(e)};
      }
      break;
    }
    e = n;
  }
  return first_step(mesh, pred, from_u, mesh.point(v));
}

RayStep next_step(const Mesh& mesh, Predicates& pred, EdgeRef g, const Point& u, const Point& q) {
  const EdgeRef h = mesh.link[g];
  if (h == kNone) return {};
  const VertexId c = mesh.apex(h);
  const double oc = pred.orient2d(u, q, mesh.point(c));
  if (oc == 0.0) return {RayStep::Kind::Vertex, lprev(h), c};
  return {RayStep::Kind::Cross, oc > 0.0 ? lnext(h) : lprev(h), kNone};
}

namespace {

using Loc = PointLocation::Kind;

// q lies strictly beyond the crossed edge g; decide inside the triangle across it or go on.
// Returns true when `out` is decided, else sets `g` to the next crossed edge or `restart` to an
// edge leaving a vertex on the line from which the walk starts over.
bool step_toward(const Mesh& mesh, Predicates& pred, const Point& u, const Point& q, EdgeRef& g,
                 EdgeRef& restart, PointLocation& out) {
  const RayStep s = next_step(mesh, pred, g, u, q);
  if (s.kind == RayStep::Kind::Boundary) return out = {Loc::Outside, g}, true;
  const EdgeRef h = mesh.link[g];
  if (s.kind == RayStep::Kind::Vertex) {
    const Point& c = mesh.point(s.vertex);
    if (pred.orient2d(mesh.point(mesh.org(lnext(h))), c, q) > 0.0 &&
        pred.orient2d(c, mesh.point(mesh.dest(lprev(h))), q) > 0.0)
      return out = {Loc::InTriangle, h}, true;
    if (c == q) return out = {Loc::OnVertex, s.edge}, true;
    restart = s.edge;
    return false;
  }
  const double o = pred.orient2d(mesh.point(mesh.org(s.edge)), mesh.point(mesh.dest(s.edge)), q);
  if (o > 0.0) return out = {Loc::InTriangle, h}, true;
  if (o == 0.0) return out = {Loc::OnEdge, s.edge}, true;
  g = s.edge;
  return false;
}

// Walks from org(from) toward q; returns true when decided, else sets `from` to the next vertex.
bool walk_from_vertex(const Mesh& mesh, Predicates& pred, EdgeRef& from, const Point& q,
                      PointLocation& out) {
  const Point& u = mesh.point(mesh.org(from));
  if (u == q) return out = {Loc::OnVertex, from}, true;
  const RayStart s = first_step(mesh, pred, from, q);
  if (s.kind == RayStart::Kind::Blocked) return out = {Loc::Outside, kNone}, true;
  if (s.kind == RayStart::Kind::Vertex) {
    const Point& w = mesh.point(s.vertex);
    if (w == q) return out = {Loc::OnVertex, s.from_vertex}, true;
    if (strictly_before(u, q, w)) return from = s.from_vertex, false;
    return out = {Loc::OnEdge, s.edge}, true;
  }
  EdgeRef g = s.edge;
  const double o = pred.orient2d(mesh.point(mesh.org(g)), mesh.point(mesh.dest(g)), q);
  if (o > 0.0) return out = {Loc::InTriangle, g}, true;
  if (o == 0.0) return out = {Loc::OnEdge, g}, true;
  EdgeRef restart = kNone;
  while (!step_toward(mesh, pred, u, q, g, restart, out))
    if (restart != kNone) return from = restart, false;
  return true;
}

}  // namespace

PointLocation walk_to_point(const Mesh& mesh, Predicates& pred, EdgeRef from, const Point& q) {
  PointLocation out;
  while (!walk_from_vertex(mesh, pred, from, q, out)) {
  }
  return out;
}

}  // namespace deltri
