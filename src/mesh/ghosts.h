// Ghost triangles: while a triangulation is built by insertion, the outside of its convex hull is
// covered by triangles with the corner kGhostVertex, one per hull edge, so that insert_vertex
// treats a point beyond the hull like any other (its Lawson flips, with a ghost's circle taken as
// the open half-plane beyond its edge, widen the hull exactly). Invariant while ghosts exist:
// every real edge has a twin, and the ghosts around the hull are linked in a ring.
#pragma once

#include "mesh/mesh.h"

namespace deltri {

// Into an empty mesh: the counter-clockwise triangle a, b, c and one ghost beyond each of its edges.
void seed_with_ghosts(Mesh& mesh, VertexId a, VertexId b, VertexId c);

// Deletes every ghost triangle and compacts the triangles (ids change); the hull edges become
// boundary edges (link kNone).
void remove_ghosts(Mesh& mesh);

}  // namespace deltri
