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

}  // namespace deltri::api

#ifndef DELTRI_INTERNAL
namespace deltri {
using api::Error;
using api::Input;
using api::Mesh;
using api::SizeFunction;
using api::triangulate;
}  // namespace deltri
#endif
