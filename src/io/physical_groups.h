// Physical groups for the formats whose groups carry positive integer tags: Gmsh MSH, of a 2-D
// mesh (io/msh_file) and of a surface in 3-D (io/surface_exports). Many solvers (GetDP, FreeFem++,
// DOLFINx via its reader) name a region by its tag alone, whatever its dimension, so a line group
// and a surface group must never share a tag: the rule below gives every group of the mesh a
// distinct tag. (The .vtu carries markers and attributes as cell values, not as groups.)
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

struct MeshPhysicalGroups {
  PhysicalGroups lines;     // by edge marker
  PhysicalGroups surfaces;  // by triangle attribute (one value for the whole domain without -A)
};

// The tag rule (docs/formats.md, "Physical groups"):
//   1. an edge marker that is a positive integer (up to 2^31 - 1) is its own tag: marker 5 is
//      physical curve 5;
//   2. the other markers (0, negative) get the next tags after the largest such marker, in
//      ascending order of marker;
//   3. the surfaces (the domain, or each triangle attribute value in ascending order) get the
//      next tags after every line tag.
// So with markers 1, 2, 3 the domain is surface 4; with markers 0 and 1 marker 0 is curve 2 and
// the domain surface 3; without lines (-B) the domain is surface 1.
MeshPhysicalGroups physical_groups(const std::vector<double>& line_markers, const std::vector<double>& surface_values);

// Rules 1 and 2 alone, for a mesh whose only groups are markers: a surface in 3-D, whose
// triangles are grouped by facet marker (no line groups to stay clear of).
PhysicalGroups marker_groups(const std::vector<double>& markers);

// The value as the files write it (shortest round-trip text).
std::string value_text(double value);

}  // namespace deltri
