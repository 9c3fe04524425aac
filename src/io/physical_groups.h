// Physical groups for the formats whose groups carry positive integer tags: Gmsh MSH, of a 2-D
// mesh (io/msh_file) and of a surface in 3-D (surface/surface_exports). Many solvers (GetDP, FreeFem++,
// DOLFINx via its reader) name a region by its tag alone, whatever its dimension, so a line group
// and a surface group must never share a tag. A solver script names its regions by number, so a
// group's tag must depend on its own value only: changing one marker must not move any other
// group. (The .vtu carries markers and attributes as cell values, not as groups.)
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
  std::string clash;        // empty, or which two groups a chosen domain tag made share a tag
};

// The tag rule (docs/formats.md, "Physical groups"), in fixed ranges that cannot overlap:
//   1. an edge marker m, an integer from 1 to 999999999, is its own tag: marker 5 is curve 5;
//   2. an edge marker m, an integer from -147483647 to 0, is tag 2000000000 - m: marker 0 is
//      2000000000, marker -1 2000000001;
//   3. the domain (without -A) is surface kDomainTag = 1000000000, or the tag the caller
//      chooses (--domain-tag); with -A the triangles of attribute a, an integer from 0 to
//      899999999, are surface domain_tag + a (attribute 0, the triangles outside every region,
//      is the domain's tag);
//   4. any other value (a fractional or negative attribute, a marker beyond those ranges) gets
//      the next tag from 1900000000 up, lines first, each kind in ascending order of value;
//      these alone depend on which such values are present.
// With the default domain tag no two groups can share a tag. A chosen one can clash with a
// marker (--domain-tag=5 with marker 5): then `clash` says which groups, and the tags are unusable.
inline constexpr long long kDomainTag = 1000000000;

MeshPhysicalGroups physical_groups(const std::vector<double>& line_markers, const std::vector<double>& surface_values,
                                   bool attributes = false, long long domain_tag = kDomainTag);

// Rules 1, 2 and 4 alone, for a mesh whose only groups are markers: a surface in 3-D, whose
// triangles are grouped by facet marker.
PhysicalGroups marker_groups(const std::vector<double>& markers);

// The value as the files write it (shortest round-trip text).
std::string value_text(double value);

}  // namespace deltri
