// The .neigh format (-n): the three neighbours of each triangle.
//   <#triangles> 3
//   <index> <t1> <t2> <t3>
// Neighbour k lies across the edge opposite corner k; -1 where there is none (whatever the
// numbering). Triangles are numbered as in the .ele: live ones in slot order.
#pragma once

#include <string>

#include "io/text_writer.h"
#include "mesh/mesh.h"

namespace deltri {

void write_neigh_file(std::string& out, const Mesh& mesh, int first_index);
void write_neigh_file(ByteSink& out, const Mesh& mesh, int first_index);

}  // namespace deltri
