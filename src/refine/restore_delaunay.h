// Restoring the constrained Delaunay property around a vertex placed by split_edge (Fig. 39
// l.44). A segment split point is rounded, so it is rarely exactly on the subsegment and
// insert_vertex's exact location would not put it there; the split is made by hand and the
// link of the new vertex is then flipped by Lawson's rule, never across a subsegment; and since
// the rounded point is not exactly on the subsegment, the edges at the new vertex are checked too.
#pragma once

#include "geometry/predicates.h"
#include "mesh/mesh.h"

namespace deltri {

// `out` leaves v. Returns an edge leaving v afterwards.
EdgeRef restore_delaunay_around(Mesh& mesh, Predicates& pred, VertexId v, EdgeRef out);

}  // namespace deltri
