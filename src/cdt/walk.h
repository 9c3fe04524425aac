// Straight-line walks through a triangulation, decided by exact orient2d only.
//
// A straight walk (rather than a visibility walk) is used because the triangulations walked here
// are constrained, not Delaunay, and a visibility walk can cycle in a non-Delaunay triangulation.
// A straight walk from a vertex toward a point makes strict progress along one line, so it can
// neither loop nor leave the mesh except through a boundary edge.
#pragma once

#include "geometry/predicates.h"
#include "mesh/mesh.h"

namespace deltri {

// The first step of a ray that starts at a vertex u and heads for point q (q != u).
struct RayStart {
  enum class Kind {
    Vertex,   // the ray runs along an edge: `vertex` is its far end, exactly on the ray
    Cross,    // the ray enters triangle_of(edge) and leaves through `edge`; u is edge's apex
    Blocked,  // the ray leaves the mesh at u
  };
  Kind kind = Kind::Blocked;
  EdgeRef edge = kNone;         // Cross: the edge crossed; Vertex: the edge u-vertex (any direction)
  VertexId vertex = kNone;      // Vertex only
  EdgeRef from_vertex = kNone;  // Vertex only: an edge leaving `vertex`, to continue the walk
};

// Examines the triangles around org(from_u) for the one the ray toward q enters.
RayStart first_step(const Mesh& mesh, Predicates& pred, EdgeRef from_u, const Point& q);

// first_step toward vertex v's point, with the same answer, found without predicates when an edge
// u-v is already there: most input segments are edges of the Delaunay triangulation.
RayStart first_step_to_vertex(const Mesh& mesh, Predicates& pred, EdgeRef from_u, VertexId v);

// One step across a crossed edge g (oriented so that the ray's origin side is on its left, its
// origin strictly right of the ray line and its destination strictly left) into the next triangle.
struct RayStep {
  enum class Kind {
    Cross,    // the ray leaves the next triangle through `edge` (same orientation convention)
    Vertex,   // the ray leaves the next triangle through its apex `vertex`, exactly on the line
    Boundary, // g is a boundary edge: there is no next triangle
  };
  Kind kind = Kind::Boundary;
  EdgeRef edge = kNone;         // Cross: the exit edge; Vertex: an edge leaving `vertex`
  VertexId vertex = kNone;
};
RayStep next_step(const Mesh& mesh, Predicates& pred, EdgeRef g, const Point& u, const Point& q);

// Whether w, known to lie exactly on the line through u and q, is on the ray from u through q.
bool on_ray_side(const Point& u, const Point& q, const Point& w);

// Where a point lies.
struct PointLocation {
  enum class Kind { InTriangle, OnEdge, OnVertex, Outside };
  Kind kind = Kind::Outside;
  EdgeRef edge = kNone;  // InTriangle: an edge of the triangle; OnEdge: the edge; OnVertex: an
                         // edge leaving the vertex
};

// Walks the straight line from org(from) to q. Outside means the line left the mesh first, which
// proves q outside only when the mesh is convex. The segment inserter uses it for points on the
// segment it is inserting, from one of its ends; point location anywhere is mesh/locate (locate()).
PointLocation walk_to_point(const Mesh& mesh, Predicates& pred, EdgeRef from, const Point& q);

}  // namespace deltri
