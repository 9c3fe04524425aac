// The last step of the sweepline (-F) and of incremental insertion (-i): Lawson flips under the
// tie-broken empty-circle test, so that both end at the one triangulation divide and conquer
// builds (Predicates::incircle_perturbed).
#pragma once

#include "geometry/predicates.h"
#include "mesh/mesh.h"

namespace deltri {

// Flips every edge of `mesh` (a triangulation of distinct points: no ghosts, no dead slots, no
// subsegments) whose far vertex is inside the circle of its triangle by incircle_perturbed, until
// none is. A triangulation with every edge locally Delaunay under that test is the unique Delaunay
// triangulation of the perturbed points, so the result does not depend on where it started. On a
// Delaunay triangulation it flips only diagonals of cocircular polygons, and each edge costs one
// incircle test (the tie rule runs only on exact zeros).
void lawson_pass(Mesh& mesh, Predicates& pred);

}  // namespace deltri
