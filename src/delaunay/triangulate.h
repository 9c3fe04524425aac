// Delaunay triangulation of a point set: the entry point the pipeline calls.
#pragma once

#include <utility>
#include <vector>

#include "geometry/predicates.h"
#include "mesh/mesh.h"

namespace deltri {

enum class DelaunayAlgorithm {
  DivideAndConquer,  // alternating cuts (default)
  VerticalCuts,      // divide and conquer with vertical cuts only (-l)
  Incremental,       // randomised incremental insertion (-i)
  Sweepline,         // Fortune's sweepline (-F)
};

struct DelaunayReport {
  // (duplicate, kept): an input vertex at the same place as an earlier one, and that earlier one.
  std::vector<std::pair<VertexId, VertexId>> duplicates;
  PredicateCounters counters;
  // -F: rounding broke the sweep (its triangles did not tile the hull); divide and conquer was used.
  bool sweepline_fell_back = false;
};

// Replaces the triangles of `mesh` by the Delaunay triangulation of its vertices of kind Input.
// Duplicates keep the lowest id; the others become VertexKind::Duplicate and are reported.
// Fewer than three distinct points or all points collinear give a mesh with no triangles.
// The result has no ghost triangles and no dead slots; boundary edges have link == kNone.
// `threads` > 1 lets divide and conquer use that many threads; the output does not depend on it.
DelaunayReport delaunay_triangulate(Mesh& mesh, DelaunayAlgorithm algorithm, int threads);

}  // namespace deltri
