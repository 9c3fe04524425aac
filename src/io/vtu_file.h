// VTK XML unstructured grid (--vtu), as ParaView and meshio read it: ASCII, or with
// --vtu-format=binary every array as raw appended data (a UInt64 byte count, then the values in
// the machine's byte order, which the byte_order attribute states).
//   Points: every vertex of the .node (z = 0), numbered from 0 in .node order.
//   Cells: the boundary and segment edges (VTK_LINE 3, or VTK_QUADRATIC_EDGE 21 with -o2; none
//   with -B), then the triangles (VTK_TRIANGLE 5, or VTK_QUADRATIC_TRIANGLE 22 with -o2) in .ele
//   order.
//   PointData: "marker" (Int32, not with -B), "attribute_<k>" (Float64) per vertex attribute.
//   CellData: "marker" (Int32: the edge marker on lines, 0 on triangles; not with -B),
//   "attribute_<k>" (Float64: the triangle attribute on triangles, 0 on lines).
#pragma once

#include "io/output_numbering.h"
#include "io/text_writer.h"
#include "mesh/mesh.h"

namespace deltri {

void write_vtu_file(ByteSink& out, const Mesh& mesh, const ExportOptions& options, bool binary = false);

}  // namespace deltri
