// Output boundary markers of the vertices, by Triangle's rules.
#pragma once

#include "mesh/mesh.h"

namespace deltri {

// Fills mesh.marker (one per vertex): a vertex keeps a non-zero input marker (only when
// input_had_markers; otherwise whatever mesh.marker holds is ignored); else it takes the non-zero
// marker of a subsegment it is an end of, the earliest such record winning (Triangle marks a
// vertex when the first marked subsegment reaching it is inserted); else 1 if it lies on the mesh
// boundary (an end of an edge with link == kNone), else 0.
// Edge markers are left to the writers, with the matching rule: the subsegment's marker if
// non-zero, else 1 on the boundary, else 0.
// With `threads` 2 or more, a large mesh's edges are scanned by two threads.
void assign_boundary_markers(Mesh& mesh, bool input_had_markers, int threads = 1);

}  // namespace deltri
