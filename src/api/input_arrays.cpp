#include "api/input_arrays.h"

#include <cmath>
#include <string>

namespace deltri {
namespace {

// The readers' limit on attributes per item (node_file.cpp, ele_file.cpp).
constexpr int kMaxAttributes = 1 << 20;

[[noreturn]] void fail(const std::string& message) { throw api::Error(DELTRI_INPUT_ERROR, message); }

std::string number_text(double x) {
  if (std::isnan(x)) return "nan";
  return x > 0 ? "inf" : "-inf";
}

void check_finite(double x, const std::string& item, const char* what) {
  if (!std::isfinite(x)) fail(item + ": " + what + " is not a finite number (" + number_text(x) + ")");
}

void check_count(std::size_t size, std::size_t per_item, const char* array, const char* what) {
  if (size % per_item != 0)
    fail(std::string(array) + ": " + std::to_string(size) + " values are not a whole number of " + what + " (" +
         std::to_string(per_item) + " each)");
}

void check_attribute_count(int count, const char* what) {
  if (count < 0 || count > kMaxAttributes)
    fail(std::string("number of ") + what + " attributes must be between 0 and " + std::to_string(kMaxAttributes) +
         ", not " + std::to_string(count));
}

// Checks that `list` holds `per_item` values for each of `items` when it is not empty (`optional`)
// or always.
void check_parallel(std::size_t size, std::size_t items, std::size_t per_item, bool optional, const char* array) {
  if (optional && size == 0) return;
  if (size != items * per_item)
    fail(std::string(array) + ": " + std::to_string(size) + " values for " + std::to_string(items) + " items, expected " +
         std::to_string(items * per_item));
}

std::string item(const char* kind, std::size_t k, int first_index) {
  return std::string(kind) + " " + std::to_string(static_cast<long long>(k) + first_index);
}

// `what` names the field: "segment 2: second endpoint 9 is not a vertex", "triangle 2: corner 3 (9)
// is not a vertex".
std::uint32_t vertex_of(long long v, std::size_t vertex_count, int first_index, const std::string& what,
                        bool parenthesized = false) {
  const long long last = first_index + static_cast<long long>(vertex_count) - 1;
  const std::string number = std::to_string(v);
  if (v < first_index || v > last)
    fail(what + (parenthesized ? " (" + number + ")" : " " + number) + " is not a vertex (vertices are numbered " + std::to_string(first_index) +
         " to " + std::to_string(last) + ")");
  return static_cast<std::uint32_t>(v - first_index);
}

void read_points(const api::Input& in, int first_index, Pslg& pslg) {
  check_count(in.points.size(), 2, "points", "points");
  const std::size_t n = in.points.size() / 2;
  if (n < 3) fail("a triangulation needs at least 3 vertices, the input has " + std::to_string(n));
  if (n > 0xFFFFFFF0u) fail("too many vertices: " + std::to_string(n));
  check_attribute_count(in.point_attribute_count, "point");
  const std::size_t na = static_cast<std::size_t>(in.point_attribute_count);
  check_parallel(in.point_attributes.size(), n, na, false, "point attributes");
  check_parallel(in.point_markers.size(), n, 1, true, "point markers");
  pslg.points.reserve(n);
  for (std::size_t k = 0; k < n; ++k) {
    const Point p{in.points[2 * k], in.points[2 * k + 1]};
    check_finite(p.x, item("vertex", k, first_index), "x coordinate");
    check_finite(p.y, item("vertex", k, first_index), "y coordinate");
    for (std::size_t a = 0; a < na; ++a)
      check_finite(in.point_attributes[k * na + a], item("vertex", k, first_index), ("attribute " + std::to_string(a + 1)).c_str());
    pslg.points.push_back(p);
  }
  pslg.num_attributes = in.point_attribute_count;
  pslg.attributes = in.point_attributes;
  pslg.has_markers = !in.point_markers.empty();
  pslg.markers = in.point_markers;
}

void read_segments(const api::Input& in, int first_index, Pslg& pslg) {
  check_count(in.segments.size(), 2, "segments", "segments");
  const std::size_t n = in.segments.size() / 2;
  check_parallel(in.segment_markers.size(), n, 1, true, "segment markers");
  pslg.has_segment_markers = !in.segment_markers.empty();
  pslg.segments.reserve(n);
  for (std::size_t k = 0; k < n; ++k) {
    const std::string name = item("segment", k, first_index);
    Pslg::Segment s;
    s.a = vertex_of(in.segments[2 * k], pslg.points.size(), first_index, name + ": first endpoint");
    s.b = vertex_of(in.segments[2 * k + 1], pslg.points.size(), first_index, name + ": second endpoint");
    if (pslg.has_segment_markers) s.marker = in.segment_markers[k];
    pslg.segments.push_back(s);
  }
}

void read_holes_and_regions(const api::Input& in, int first_index, Pslg& pslg) {
  check_count(in.holes.size(), 2, "holes", "holes");
  for (std::size_t k = 0; k < in.holes.size() / 2; ++k) {
    const Point p{in.holes[2 * k], in.holes[2 * k + 1]};
    check_finite(p.x, item("hole", k, first_index), "x coordinate");
    check_finite(p.y, item("hole", k, first_index), "y coordinate");
    pslg.holes.push_back(p);
  }
  check_count(in.regions.size(), 4, "regions", "regions");
  for (std::size_t k = 0; k < in.regions.size() / 4; ++k) {
    const double* r = &in.regions[4 * k];
    const std::string name = item("region", k, first_index);
    check_finite(r[0], name, "x coordinate");
    check_finite(r[1], name, "y coordinate");
    check_finite(r[2], name, "attribute");
    check_finite(r[3], name, "maximum area");
    pslg.regions.push_back({{r[0], r[1]}, r[2], r[3]});
  }
}

}  // namespace

Pslg pslg_from_input(const api::Input& in, int first_index, bool poly) {
  Pslg pslg;
  pslg.first_index = first_index;
  read_points(in, first_index, pslg);
  if (poly) {
    read_segments(in, first_index, pslg);
    read_holes_and_regions(in, first_index, pslg);
    pslg.has_segment_section = true;
  }
  return pslg;
}

PreviousMesh previous_from_input(const api::Input& in, int first_index, bool area_bounds) {
  PreviousMesh previous;
  previous.ele_name = "triangles";
  EleData& ele = previous.ele;
  if (in.corner_count != 3 && in.corner_count != 6)
    fail("corners per triangle must be 3 or 6, not " + std::to_string(in.corner_count));
  ele.nodes_per_triangle = static_cast<std::uint32_t>(in.corner_count);
  check_count(in.triangles.size(), ele.nodes_per_triangle, "triangles", "triangles");
  const std::size_t n = in.triangles.size() / ele.nodes_per_triangle;
  if (n == 0) fail("r: the input lists no triangles: the mesh is empty");
  check_attribute_count(in.triangle_attribute_count, "triangle");
  ele.num_attributes = in.triangle_attribute_count;
  const std::size_t na = static_cast<std::size_t>(ele.num_attributes);
  check_parallel(in.triangle_attributes.size(), n, na, false, "triangle attributes");
  const std::size_t vertices = in.points.size() / 2;
  ele.corners.reserve(in.triangles.size());
  for (std::size_t k = 0; k < n; ++k) {
    const std::string name = item("triangle", k, first_index);
    for (std::uint32_t c = 0; c < ele.nodes_per_triangle; ++c)
      ele.corners.push_back(vertex_of(in.triangles[k * ele.nodes_per_triangle + c], vertices, first_index,
                                      name + ": corner " + std::to_string(c + 1), true));
    for (std::size_t a = 0; a < na; ++a)
      check_finite(in.triangle_attributes[k * na + a], name, ("attribute " + std::to_string(a + 1)).c_str());
  }
  ele.attributes = in.triangle_attributes;
  if (area_bounds && !in.triangle_areas.empty()) {
    check_parallel(in.triangle_areas.size(), n, 1, false, "triangle areas");
    for (std::size_t k = 0; k < n; ++k)
      if (std::isnan(in.triangle_areas[k])) fail(item("triangle", k, first_index) + ": area bound is not a number (nan)");
    previous.area_bounds = true;
    previous.areas = in.triangle_areas;
  }
  return previous;
}

}  // namespace deltri
