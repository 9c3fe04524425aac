#pragma once
// A vertex's star as the searches that move a vertex read it (refinement's relocation,
// refine/relocation.h, and --smooth, improve/smooth.cpp): the edges leaving it and their far ends.

#include <vector>

#include "mesh/mesh.h"

namespace deltri {

// Triangle i of the star is (org(out[0]), ring[i], ring[i + 1]).
struct Star {
  std::vector<EdgeRef> out;    // the edges leaving the vertex, counter-clockwise
  std::vector<VertexId> ring;  // their far ends: ring.size() == out.size() + 1, ring.back() == ring.front()
};

// The star of org(first) into `star`; false where the fan is open (the vertex on the boundary),
// a spoke carries a subsegment, or it has fewer than three triangles.
bool gather_star(const Mesh& m, EdgeRef first, Star& star);

}  // namespace deltri
