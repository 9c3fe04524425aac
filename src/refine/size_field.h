// A background size field (the command line's --size-field, TetGen's .mtr idea): a triangle mesh
// whose vertices carry the wanted edge length h, linearly interpolated over each background
// triangle. Outside every background triangle h is that of the nearest background vertex.
//
// The rule refinement applies (refine/size_test.h): a triangle is too big when its area is larger
// than that of the equilateral triangle of edge h, sqrt(3)/4 h^2, with h taken at its centroid. So a
// mesh that meets it needs at least about the integral of 4 / (sqrt(3) h^2) over the domain
// triangles; deltri's meshes have about 1.6 times that (docs/library.md). An area rather than an
// edge rule: an edge rule cost 2.6 times the bound (measured on the same kind of field), and with
// -q the triangles are well shaped, so their edges stay close to h (at most 1.65 h there).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "geometry/point.h"
#include "geometry/triangle_grid.h"
#include "refine/size_test.h"

namespace deltri {

class SizeField {
 public:
  // `corners`: three vertex ids per triangle; `lengths`: h at each vertex, positive and finite
  // (the caller checks). Triangles whose corners are collinear are skipped.
  SizeField(std::vector<Point> points, std::vector<double> lengths, const std::vector<std::uint32_t>& corners);

  double length_at(const Point& p) const;
  // The rule above as a size test; it refers to this field, which must outlive it.
  SizeTest test() const;

 private:
  struct Triangle {
    std::uint32_t v[3];
  };
  bool interpolate(const Triangle& t, const Point& p, double& h) const;
  double nearest_vertex_length(const Point& p) const;
  std::vector<Point> points_;
  std::vector<double> lengths_;
  std::vector<Triangle> triangles_;
  TriangleGrid grid_;
};

}  // namespace deltri
