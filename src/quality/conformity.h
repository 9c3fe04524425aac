// Which subsegments keep a mesh refined with -D (conforming Delaunay) from being Delaunay: the
// subsegment edges between two triangles that fail the empty-circle test (exact incircle), counted
// on the final mesh as bound_misses.h counts triangles, whatever refinement believes. Refinement
// leaves such a subsegment when it could not split it: the split point rounds onto an end or to
// the wrong side of a vertex flush with the segment (double precision), or the termination guard
// refused the split, as it does where Ruppert's midpoint splitting ping-pongs between segments
// that meet at a small angle (docs/refinement.md, "Corpus sweep of the paper's modes").
#pragma once

#include <cstdint>

#include "mesh/mesh.h"

namespace deltri {

struct ConformityMisses {
  std::uint64_t total = 0;  // subsegment edges not locally Delaunay
  // Of those: the subsegment is at most kPrecisionUlps ulps long, or its rounded midpoint would
  // make a triangle with an apex clockwise or flat (an apex flush with its line): no double splits
  // it usefully.
  std::uint64_t double_precision = 0;
  std::uint64_t other() const { return total - double_precision; }
};

ConformityMisses count_conformity_misses(const Mesh& mesh);

}  // namespace deltri
