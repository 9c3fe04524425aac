// A picture of the mesh (--svg) that any browser opens. Triangles are filled by their smallest
// angle in six 10-degree shades, one <path> per shade, so 100k triangles cost about 3 MB and a few
// elements rather than 100k; segments are drawn over them in one black <path>, hole points as red
// rings, and with --svg-numbers every vertex gets its .node number. Coordinates are scaled to a
// 10000-unit-wide canvas and rounded to whole units (0.01% of the width); y points up as in the
// input.
#pragma once

#include <vector>

#include "geometry/point.h"
#include "io/output_numbering.h"
#include "io/text_writer.h"
#include "mesh/mesh.h"

namespace deltri {

struct SvgOptions {
  ExportOptions mesh;
  int first_index = 1;          // for vertex numbers
  bool vertex_numbers = false;  // --svg-numbers
  std::vector<Point> holes;
};

void write_svg_file(ByteSink& out, const Mesh& mesh, const SvgOptions& options);

// The smallest angle of triangle abc in degrees (0 for a degenerate one).
double smallest_angle_degrees(const Point& a, const Point& b, const Point& c);

}  // namespace deltri
