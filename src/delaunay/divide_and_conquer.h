// Divide-and-conquer Delaunay triangulation (Guibas and Stolfi's merge, Dwyer's alternating cuts).
#pragma once

#include <utility>
#include <vector>

#include "geometry/predicates.h"
#include "mesh/mesh.h"

namespace deltri {

struct DivideAndConquerOptions {
  bool alternate_cuts = true;  // false: vertical cuts only (-l)
  int threads = 1;             // 2 lets the two top halves be built at once
};

// Triangulates the vertices of kind Input. See delaunay_triangulate for the contract; duplicates
// are appended to `duplicates` and prediction counters added to `counters`.
void divide_and_conquer_delaunay(Mesh& mesh, const DivideAndConquerOptions& options,
                                 std::vector<std::pair<VertexId, VertexId>>& duplicates,
                                 PredicateCounters& counters);

}  // namespace deltri
