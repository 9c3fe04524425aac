// Gmsh MSH 4.1, ASCII (--msh): the whole mesh in one file that Gmsh and most solvers read.
//   $MeshFormat 4.1 0 8, $PhysicalNames, $Entities (curves, surfaces), $Nodes, $Elements,
//   and $NodeData views "marker" and "attribute <k>".
// Nodes are numbered as in the .node written with -z off (1, 2, ...; with -j the kept vertices);
// all of them sit in one node block of surface 1. Triangles (type 2, or 9 with -o2) are grouped
// into one surface per triangle attribute value (one surface when there are none); boundary and
// segment edges (type 1, or 8 with -o2) into one curve per edge marker (none with -B). A group's
// physical tag is its marker or attribute when that is a positive integer, otherwise a number
// above all of those; $PhysicalNames says which ("marker 0", "attribute 2.5", "domain").
#pragma once

#include "io/output_numbering.h"
#include "io/text_writer.h"
#include "mesh/mesh.h"

namespace deltri {

void write_msh_file(ByteSink& out, const Mesh& mesh, const ExportOptions& options);

}  // namespace deltri
