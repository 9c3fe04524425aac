// A piecewise linear complex of planar facets in 3-D, as read from TetGen's .poly (3-D node section)
// or .smesh: plain data, no mesh. Indices are 0-based here; first_index remembers the file's.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "geometry/point3.h"

namespace deltri {

// The one message for a facet corner that names no point (the facet reader's and the library's).
inline std::string corner_not_a_point(long long facet, long long corner, long long first, long long last) {
  return "facet " + std::to_string(facet) + ": corner " + std::to_string(corner) + " is not a point (points are numbered " +
         std::to_string(first) + " to " + std::to_string(last) + ")";
}

struct FacetInput {
  struct Facet {
    // Each polygon is a list of vertex indices: one index is a lone vertex in the facet, two a
    // segment, three or more a closed loop of segments.
    std::vector<std::vector<std::uint32_t>> polygons;
    std::vector<Point3> holes;  // points in the facet's plane whose enclosed part is left out
    std::vector<long> hole_lines;  // each hole's line in the file, for messages (empty: the facet's line)
    int marker = 0;
    long line = 0;              // the facet's first line in the file, for messages
  };

  std::vector<Point3> points;
  bool has_markers = false;
  std::vector<int> markers;   // one per point when has_markers
  int first_index = 1;        // 0 or 1, from the first vertex line
  std::vector<Facet> facets;
  std::string source_name;    // the file the facets came from, for messages
};

}  // namespace deltri
