// deltri's C++ library: value types in, value types out, one exception type. Reentrant: no
// global state, so calls from many threads at once give the same results as one at a time.
// See docs/library.md.
#pragma once

#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "deltri/triangle.h"  // DELTRI_EXPORT, the status codes

// The types live in deltri::api and are named deltri::Input, deltri::Mesh, ... through the
// using-declarations at the end (the library's own sources, which have an internal deltri::Mesh,
// define DELTRI_INTERNAL and say deltri::api::).
namespace deltri::api {

// What to triangulate. Item numbers (segments, triangles) start at 1, or at 0 with the switch z,
// as in Triangle's files and library.
struct Input {
  std::vector<double> points;              // x, y per point
  int point_attribute_count = 0;
  std::vector<double> point_attributes;    // point_attribute_count per point
  std::vector<int> point_markers;          // one per point, or empty: all 0
  std::vector<int> segments;               // p: two endpoints per segment
  std::vector<int> segment_markers;        // one per segment, or empty: all 0
  std::vector<double> holes;               // p: x, y per hole
  std::vector<double> regions;             // p: x, y, attribute, maximum area (<= 0: none) per region
  // r: the mesh to refine, with its triangle attributes and (bare a) area bounds (<= 0: none).
  std::vector<int> triangles;              // corner_count per triangle, counter-clockwise
  int corner_count = 3;                    // 3, or 6 (only the first three are read)
  int triangle_attribute_count = 0;
  std::vector<double> triangle_attributes;
  std::vector<double> triangle_areas;      // one per triangle, or empty: none
};

// The result, numbered as the input (z: from 0). Which arrays are filled follows the switches,
// as in Triangle; the counts are always set.
struct Mesh {
  int point_count = 0;
  int point_attribute_count = 0;
  std::vector<double> points;              // unless N
  std::vector<double> point_attributes;
  std::vector<int> point_markers;          // unless B
  int triangle_count = 0;
  int corner_count = 3;                    // 6 with o2
  int triangle_attribute_count = 0;
  std::vector<int> triangles;              // unless E
  std::vector<double> triangle_attributes;
  std::vector<int> neighbors;              // n: 3 per triangle, neighbour k opposite corner k, -1: none
  int segment_count = 0;
  std::vector<int> segments;               // p or c, unless P
  std::vector<int> segment_markers;        // and unless B
  int edge_count = 0;
  std::vector<int> edges;                  // e
  std::vector<int> edge_markers;           // e, unless B
  // v: one Voronoi vertex per triangle (its circumcentre) and one Voronoi edge per edge: the two
  // vertices, or for a ray the vertex and -1 with the ray's direction in voronoi_normals.
  std::vector<double> voronoi_points;
  std::vector<double> voronoi_point_attributes;  // point_attribute_count per Voronoi vertex
  std::vector<int> voronoi_edges;
  std::vector<double> voronoi_normals;     // 2 per Voronoi edge; (0, 0) for a finite one
};

// The one exception: what() is a one-line message naming the input item
// ("segment 3: second endpoint 7 is not a vertex (vertices are numbered 1 to 4)"), code() the
// DELTRI_... status of deltri/triangle.h.
class DELTRI_EXPORT Error : public std::runtime_error {
 public:
  Error(int code, const std::string& message) : std::runtime_error(message), code_(code) {}
  int code() const { return code_; }

 private:
  int code_;
};

// A size test: the corners of a triangle, counter-clockwise, and its area; true means "too big,
// split it". Called only from the calling thread.
using SizeFunction = std::function<bool(const double* org, const double* dest, const double* apex, double area)>;

// Triangulates `input` as Triangle's switches say ("pq30a0.1", no dash). Prints nothing; throws
// deltri::Error. A size function, if given, is applied along with the switches' bounds.
DELTRI_EXPORT Mesh triangulate(const Input& input, const std::string& switches, const SizeFunction& size = {});


// Facets in 3-D (docs/surfaces.md), as TetGen's .poly and .smesh carry them: points in space and
// planar facets, each a list of polygons (vertex numbers: one is a vertex in the facet, two a
// segment, three or more a closed loop), hole points in its plane and a marker. Vertex numbers
// start at 1, or at 0 with the switch z.
struct Facet {
  std::vector<std::vector<int>> polygons;
  std::vector<double> holes;               // x, y, z per hole point
  int marker = 0;
};
struct Facets {
  std::vector<double> points;              // x, y, z per point
  std::vector<int> point_markers;          // one per point, or empty: none
  std::vector<Facet> facets;
};

// The surface mesh, numbered as the input (z: from 0): the input's points first, then the new ones.
struct Surface {
  int point_count = 0;
  std::vector<double> points;              // x, y, z per point
  std::vector<int> point_markers;          // when the input has them, unless B (0 for new points)
  int triangle_count = 0;
  std::vector<int> triangles;              // three corners per triangle, wound about its facet's normal
  std::vector<double> triangle_attributes; // one per triangle: its facet's marker
  std::vector<int> triangle_facets;        // one per triangle: its facet's number
  int edge_count = 0;
  std::vector<int> edges;                  // two ends per subsegment (every piece of every input segment)
  std::vector<int> edge_markers;           // one per subsegment, unless B: the marker of the first facet holding it
  // What the result is not, as the command line warns of it (docs/surfaces.md):
  std::vector<int> merged_points;          // two per point that repeats an earlier point's coordinates: it, the earlier one
  std::vector<int> emptied_facets;         // facets left with no triangle (a hole point and no inner loop about it)
  bool budget_reached = false;             // the Steiner budget (-S, or the termination guard's) ended the run
  bool rounds_exhausted = false;           // the facets did not agree on shared segments within the round cap
  int triangles_below_angle = 0;           // when either of the two above: triangles below the -q angle
  int triangles_above_area = 0;            //   and above the -a area
  std::vector<std::string> warnings;       // the command line's warnings, word for word (without "deltri: warning: ")
};

// Meshes the facets as the switches say ("pq30a0.02", as for deltri -pq30a0.02 on a .poly with a
// 3-D node section: the same mesh as the command line's files). Prints nothing; throws
// deltri::Error (a facet that is not planar: "input: facet 3: not planar: ...").
DELTRI_EXPORT Surface mesh_surface(const Facets& facets, const std::string& switches);

}  // namespace deltri::api

#ifndef DELTRI_INTERNAL
namespace deltri {
using api::Error;
using api::Facet;
using api::Facets;
using api::mesh_surface;
using api::Input;
using api::Mesh;
using api::SizeFunction;
using api::Surface;
using api::triangulate;
}  // namespace deltri
#endif
