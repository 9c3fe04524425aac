// Deleting a vertex from a (constrained) Delaunay triangulation, for Chew's step of Delaunay
// refinement with diametral lenses (Shewchuk 2001, Fig. 39 l.40).
//
// The star of v is emptied by flips, one ear of its link polygon at a time, until three triangles
// are left, which merge into one. The ear cut first is one whose circumcircle holds no other link
// vertex (exact incircle): such an ear is a triangle of the Delaunay triangulation of the link
// polygon, which is what fills the hole in the Delaunay triangulation of the other vertices, and
// one always exists for a star-shaped polygon (the Delaunay triangulation of the link, restricted
// to it, has at least two ears). The whole sequence of ears is chosen on the list of link vertices
// before the mesh is touched, so a vertex that cannot be deleted leaves the mesh exactly as it was.
// This is the simple O(m^2) method the paper recommends for the small degrees met in practice.
#pragma once

#include <vector>

#include "geometry/predicates.h"
#include "mesh/mesh.h"

namespace deltri {

// Deletes org(out) if it is an interior vertex (every edge around it has a twin) and no edge at it
// carries a subsegment. Appends the triangles that now fill its star to `created` and marks the
// vertex Dead. Returns false, changing nothing, if the vertex is not deletable.
bool delete_vertex(Mesh& mesh, Predicates& pred, EdgeRef out, std::vector<TriangleId>& created);

}  // namespace deltri
