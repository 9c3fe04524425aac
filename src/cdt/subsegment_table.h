// Housekeeping of mesh.subsegments shared by the segment and hole stages.
#pragma once

#include "mesh/mesh.h"

namespace deltri {

// Records with a == kNone are dead. Removes them, keeping the others in order, and renumbers the
// ids stored on edges, so consumers never see a dead record.
void drop_dead_subsegments(Mesh& mesh);

}  // namespace deltri
