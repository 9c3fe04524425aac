// Refinement's name for the kernel's vertex-to-edge index (mesh/vertex_edges.h), kept lazily:
// refinement notes the stars it looks at and lets lookups repair stale entries.
#pragma once

#include "mesh/vertex_edges.h"

namespace deltri {

using EdgeFinder = VertexEdges;

}  // namespace deltri
