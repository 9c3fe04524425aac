// Randomised incremental Delaunay triangulation (Lawson flips, ghost triangles for the outside).
// Slower than divide and conquer; used for -i and as an independent oracle in tests.
#pragma once

#include <utility>
#include <vector>

#include "geometry/predicates.h"
#include "mesh/mesh.h"

namespace deltri {

// Replaces the triangles of `mesh` by the Delaunay triangulation of its vertices of kind Input.
// An Input vertex at the same place as a lower-numbered one becomes VertexKind::Duplicate and
// (duplicate, kept) is appended to `duplicates`, in increasing order of the duplicate. Fewer than
// three distinct points, or all of them collinear, leave no triangles. The insertion order is a
// fixed-seed shuffle cut into rounds sorted along a Hilbert curve, so the output is the same on
// every run; cocircular ties end as Predicates::incircle_perturbed breaks them, so the triangles are
// divide and conquer's. The result has no ghosts and no dead slots; boundary edges have
// link == kNone; triangle attribute and area-bound arrays are emptied.
void incremental_delaunay(Mesh& mesh, Predicates& pred,
                          std::vector<std::pair<VertexId, VertexId>>& duplicates);

// Empties the mesh's triangles (and their attribute, area-bound and subsegment arrays) and returns
// the Input vertices without repeats (lowest id kept), in increasing id order; each repeat becomes
// VertexKind::Duplicate and (duplicate, kept) is appended to `duplicates` in increasing order of
// the duplicate. Shared with the sweepline.
std::vector<VertexId> distinct_inputs(Mesh& mesh, std::vector<std::pair<VertexId, VertexId>>& duplicates);

}  // namespace deltri
