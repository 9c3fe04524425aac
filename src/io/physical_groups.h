// Grouping of elements by a value (an edge marker, a triangle attribute) for formats whose groups
// carry positive integer tags (Gmsh physical groups).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace deltri {

struct PhysicalGroups {
  std::vector<double> values;        // distinct values, ascending; group g holds values[g]
  std::vector<long long> tags;       // the physical tag of each group
  std::vector<std::uint32_t> group;  // per element: its group
};

// A value that is a positive integer (up to 2^31 - 1) is its own tag, so a marker 5 stays
// physical group 5; the other values get the tags after the largest such value, in ascending
// order of value.
PhysicalGroups group_by_value(const std::vector<double>& per_element);

// The value as the files write it (shortest round-trip text).
std::string value_text(double value);

}  // namespace deltri
