// Geomview's OFF format (-g):
//   OFF
//   <#vertices> <#triangles> <#edges>
//   <x> <y> 0                 one line per vertex, in .node order
//   3 <a> <b> <c>             one line per triangle, in .ele order, corners counter-clockwise
// Vertices are numbered from 0 whatever -z and the input say: OFF has no index column.
#pragma once

#include <cstdint>
#include <vector>

#include "io/text_writer.h"
#include "mesh/mesh.h"

namespace deltri {

// `numbering` as in NodeWriteOptions (nullptr: every vertex in id order).
void write_off_file(ByteSink& out, const Mesh& mesh, const std::vector<std::uint32_t>* numbering);

}  // namespace deltri
