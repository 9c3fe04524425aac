// Deleting whole triangles: the holes and concavities of a domain, carved out after the segments
// are in.
#pragma once

#include <span>

#include "mesh/mesh.h"

namespace deltri {

// Marks every triangle of `dead` (live, no repeats) dead and puts it on the free list. The edges
// of surviving neighbours that faced them become boundary edges (link kNone) and keep their
// subsegments; the dead slots' subsegment entries stay until drop_unused_subsegments clears them.
void remove_triangles(Mesh& mesh, std::span<const TriangleId> dead);

}  // namespace deltri
