// -o2: the midpoint of every edge becomes a vertex, so that each triangle has six nodes.
#pragma once

#include <vector>

#include "mesh/mesh.h"

namespace deltri {

// Appends one vertex per edge at its midpoint, in the order the .edge file lists the edges, and
// returns three ids per triangle slot: the midpoints of the edges opposite corners 0, 1 and 2
// (kNone for dead slots). A midpoint's attributes are the mean of its edge's ends; its marker is
// the edge's (see edge_marker), so a midpoint of a marked segment carries the segment's marker.
// The triangles do not use the new vertices: the mesh stays a valid three-node triangulation.
std::vector<VertexId> add_edge_midpoints(Mesh& mesh);

}  // namespace deltri
