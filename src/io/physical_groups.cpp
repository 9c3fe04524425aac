#include "io/physical_groups.h"

#include <algorithm>
#include <charconv>
#include <map>

namespace deltri {
namespace {

constexpr long long kLastMarkerTag = 999999999;
constexpr long long kLastAttribute = 899999999;
constexpr long long kOtherTags = 1900000000;
constexpr long long kNonPositiveTags = 2000000000;
constexpr long long kLargestTag = 2147483647;

bool integer_in(double v, long long low, long long high) {
  return v >= static_cast<double>(low) && v <= static_cast<double>(high) && v == static_cast<double>(static_cast<long long>(v));
}

// Rules 1 and 2; 0 for a marker that rule 4 must tag.
long long marker_tag(double v) {
  if (integer_in(v, 1, kLastMarkerTag)) return static_cast<long long>(v);
  if (integer_in(v, kNonPositiveTags - kLargestTag, 0)) return kNonPositiveTags - static_cast<long long>(v);
  return 0;
}

// Rule 3; 0 for an attribute that rule 4 must tag.
long long attribute_tag(double a, long long domain_tag) {
  const long long last = domain_tag == kDomainTag ? kLastAttribute : kLargestTag - domain_tag;
  return integer_in(a, 0, last) ? domain_tag + static_cast<long long>(a) : 0;
}

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

// Tags g's values by `rule`, rule 4 for those it leaves at 0 (from `next` up, which it advances).
template <class Rule>
void tag_groups(PhysicalGroups& g, long long& next, Rule rule) {
  for (double v : g.values) {
    const long long tag = rule(v);
    g.tags.push_back(tag != 0 ? tag : next++);
  }
}

std::string group_name(int dim, double value, bool attributes) {
  if (dim == 1) return "marker " + value_text(value);
  return attributes ? "attribute " + value_text(value) : std::string("the domain");
}

// Which two groups share a tag, if any (only a chosen domain tag can make them).
std::string find_clash(const MeshPhysicalGroups& m, bool attributes) {
  std::map<long long, std::string> owner;
  for (int dim : {1, 2}) {
    const PhysicalGroups& g = dim == 1 ? m.lines : m.surfaces;
    for (std::size_t k = 0; k < g.values.size(); ++k) {
      const std::string name = group_name(dim, g.values[k], attributes);
      const auto [it, fresh] = owner.emplace(g.tags[k], name);
      if (!fresh) return "tag " + std::to_string(g.tags[k]) + " would be both " + it->second + "'s and " + name + "'s";
    }
  }
  return {};
}

}  // namespace

MeshPhysicalGroups physical_groups(const std::vector<double>& line_markers, const std::vector<double>& surface_values,
                                   bool attributes, long long domain_tag) {
  MeshPhysicalGroups m{group(line_markers), group(surface_values), {}};
  long long next = kOtherTags;
  tag_groups(m.lines, next, marker_tag);
  tag_groups(m.surfaces, next, [&](double a) { return attributes ? attribute_tag(a, domain_tag) : domain_tag; });
  if (domain_tag != kDomainTag) m.clash = find_clash(m, attributes);
  return m;
}

PhysicalGroups marker_groups(const std::vector<double>& markers) {
  PhysicalGroups g = group(markers);
  long long next = kOtherTags;
  tag_groups(g, next, marker_tag);
  return g;
}

std::string value_text(double value) {
  char buffer[32];
  return std::string(buffer, std::to_chars(buffer, buffer + sizeof buffer, value).ptr);
}

}  // namespace deltri
