// -c: the convex hull of the vertices is part of the domain, so its edges become segments.
#pragma once

#include <cstddef>

#include "mesh/mesh.h"

namespace deltri {

// Gives every boundary edge (link == kNone) without a subsegment a subsegment with marker 1 and
// segment index kNone (it comes from no input segment). Marker 1 is what Triangle gives hull
// edges, and what the boundary rule would give them anyway. Call after insert_segments and before
// carve_holes (with keep_convex_hull). Returns the number of subsegments added.
std::size_t enclose_convex_hull(Mesh& mesh);

}  // namespace deltri
