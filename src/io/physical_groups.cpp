#include "io/physical_groups.h"

#include <algorithm>
#include <charconv>

namespace deltri {
namespace {

bool own_tag(double v) { return v >= 1.0 && v <= 2147483647.0 && v == static_cast<double>(static_cast<long long>(v)); }

// Distinct values and each element's group; no tags yet.
PhysicalGroups group(const std::vector<double>& per_element) {
  PhysicalGroups g;
  g.values = per_element;
  std::sort(g.values.begin(), g.values.end());
  g.values.erase(std::unique(g.values.begin(), g.values.end()), g.values.end());
  g.group.reserve(per_element.size());
  for (double v : per_element)
    g.group.push_back(static_cast<std::uint32_t>(std::lower_bound(g.values.begin(), g.values.end(), v) - g.values.begin()));
  return g;
}

// Rules 1 and 2 on g's values; returns the first tag after them.
long long tag_markers(PhysicalGroups& g) {
  long long next = 1;
  for (double v : g.values)
    if (own_tag(v)) next = std::max(next, static_cast<long long>(v) + 1);
  for (double v : g.values) g.tags.push_back(own_tag(v) ? static_cast<long long>(v) : next++);
  return next;
}

}  // namespace

MeshPhysicalGroups physical_groups(const std::vector<double>& line_markers, const std::vector<double>& surface_values) {
  MeshPhysicalGroups m{group(line_markers), group(surface_values)};
  long long next = tag_markers(m.lines);
  for (std::size_t g = 0; g < m.surfaces.values.size(); ++g) m.surfaces.tags.push_back(next++);
  return m;
}

PhysicalGroups marker_groups(const std::vector<double>& markers) {
  PhysicalGroups g = group(markers);
  tag_markers(g);
  return g;
}

std::string value_text(double value) {
  char buffer[32];
  return std::string(buffer, std::to_chars(buffer, buffer + sizeof buffer, value).ptr);
}

}  // namespace deltri
