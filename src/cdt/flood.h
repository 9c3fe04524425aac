// Flood fill over triangles across edges that carry no subsegment.
#pragma once

#include <cstdint>
#include <vector>

#include "mesh/mesh.h"

namespace deltri {

// Marks (with `mark`) every triangle reachable from the seeds without crossing a subsegment and
// returns them. `marks` has one entry per triangle slot; triangles already carrying `mark` are
// not entered.
std::vector<TriangleId> flood(const Mesh& mesh, std::vector<TriangleId> seeds, std::vector<std::uint32_t>& marks,
           std::uint32_t mark);

}  // namespace deltri
