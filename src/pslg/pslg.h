// A planar straight line graph as read from the input: plain data, no mesh. Indices are 0-based
// here whatever the file used; first_index remembers the file's numbering for the output.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "geometry/point.h"
#include "util/big_allocator.h"

namespace deltri {

struct Pslg {
  struct Segment {
    std::uint32_t a = 0, b = 0;
    int marker = 0;
  };
  struct Region {
    Point at;
    double attribute = 0.0;
    double max_area = -1.0;  // <= 0: no bound
  };

  BigVector<Point> points;
  int num_attributes = 0;
  std::vector<double> attributes;  // num_attributes per point
  bool has_markers = false;
  std::vector<int> markers;        // one per point when has_markers
  int first_index = 1;             // 0 or 1, from the first vertex line of the file
  // False when the first vertex's index was neither 0 nor 1: the output is then numbered from 1,
  // or from 0 with -z, as in Triangle.
  bool numbered_by_file = true;
  // Where the vertex indices do not follow the first one consecutively (Triangle ignores them):
  // the first such line, 0 if none. What refers to vertices by number (segments, a .ele) is then
  // ambiguous, and refused (require_regular_numbering in io/node_file.h).
  long irregular_index_line = 0;
  std::string irregular_index_text;  // the problem at that line, for the error

  // What a lenient reading assumed, one line each ("file:line: what"), for warnings: things
  // Triangle reads whose meaning is plain (a missing trailing marker, a segment naming no vertex).
  std::vector<std::string> read_warnings;

  bool has_segment_markers = false;
  std::vector<Segment> segments;
  std::vector<Point> holes;
  std::vector<Region> regions;
  bool has_segment_section = false;  // true when read from a .poly

  std::string source_name;  // file the vertices came from, for messages
};

}  // namespace deltri
