#include "surface/facet_plane.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "util/errors.h"

namespace deltri {
namespace {

// The facet's points relative to its first one, times a power of two that brings their largest
// coordinate difference to [1, 2): squared lengths and cross products of the facet's own extent
// then neither overflow nor underflow, whatever its scale (1e-100 or 1e155), and the scaling is
// exact, so the plane is that of the points as given. `unit` is that power of two's inverse.
std::vector<Point3> facet_points(const FacetInput& input, const FacetInput::Facet& facet, double& unit) {
  std::vector<Point3> points;
  for (const auto& polygon : facet.polygons)
    for (std::uint32_t v : polygon) points.push_back(input.points[v]);
  const Point3 first = points[0];
  double extent = 0.0;
  for (Point3& p : points) {
    p = p - first;
    extent = std::max({extent, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
  }
  const int e = extent > 0.0 && std::isfinite(extent) ? std::ilogb(extent) : 0;
  unit = std::ldexp(1.0, e);
  for (Point3& p : points) p = {std::ldexp(p.x, -e), std::ldexp(p.y, -e), std::ldexp(p.z, -e)};
  return points;
}

// Newell's normal of one closed polygon: twice its vector area, whatever its shape (in the scaled
// coordinates of facet_points, where `at` gives each corner).
template <class At>
Point3 newell(const std::vector<std::uint32_t>& polygon, At at) {
  Point3 n;
  for (std::size_t i = 0; i < polygon.size(); ++i) n = n + cross(at(i), at((i + 1) % polygon.size()));
  return n;
}

// A normal from three of the points spanning the widest triangle from the first one: it tells
// whether the facet spans a plane at all.
Point3 spanning_normal(const std::vector<Point3>& points, double& diameter) {
  const Point3& a = points[0];
  std::size_t far = 0;
  for (std::size_t i = 1; i < points.size(); ++i)
    if (norm(points[i] - a) > norm(points[far] - a)) far = i;
  diameter = 2.0 * norm(points[far] - a);
  Point3 best;
  for (const Point3& c : points) {
    const Point3 n = cross(points[far] - a, c - a);
    if (norm(n) > norm(best)) best = n;
  }
  return best;
}

[[noreturn]] void fail(const FacetInput& input, std::size_t f, const std::string& what) {
  throw InputError(input.source_name, input.facets[f].line,
                   "facet " + std::to_string(f + static_cast<std::size_t>(input.first_index)) + ": " + what);
}

}  // namespace

FacetPlane fit_facet_plane(const FacetInput& input, std::size_t f) {
  const FacetInput::Facet& facet = input.facets[f];
  double unit = 1.0;
  const std::vector<Point3> points = facet_points(input, facet, unit);
  // Each polygon's corners in `points`, which lists them polygon by polygon.
  std::vector<std::size_t> polygon_start;
  for (std::size_t i = 0, at = 0; i < facet.polygons.size(); at += facet.polygons[i++].size()) polygon_start.push_back(at);
  const auto polygon_newell = [&](std::size_t i) {
    return newell(facet.polygons[i], [&](std::size_t k) { return points[polygon_start[i] + k]; });
  };
  FacetPlane plane;
  double diameter = 0.0;  // in the scaled coordinates, about 1 unless the facet is one point
  const Point3 guide = spanning_normal(points, diameter);
  // Collinear (or one point): no plane. The cross product of the widest pair is at least
  // diameter^2 * sin(angle), so this refuses angles below about 1e-12 radians.
  if (norm(guide) <= 1e-12 * diameter * diameter / 4 || diameter == 0.0)
    fail(input, f, "its points are collinear, so it spans no plane");
  plane.diameter = diameter * unit;
  // The triangles wind about the normal as the facet's first loop does (outward, when the input's
  // loops are written so): its Newell normal, where it has one, sets the sign.
  Point3 sign = guide;
  for (std::size_t i = 0; i < facet.polygons.size(); ++i)
    if (facet.polygons[i].size() >= 3 && norm(polygon_newell(i)) > 1e-12 * norm(guide)) {
      sign = polygon_newell(i);
      break;
    }
  Point3 normal;
  for (std::size_t i = 0; i < facet.polygons.size(); ++i) {
    if (facet.polygons[i].size() < 3) continue;
    const Point3 n = polygon_newell(i);
    normal = dot(n, sign) >= 0.0 ? normal + n : normal - n;
  }
  if (norm(normal) <= 1e-12 * norm(guide)) normal = sign;  // only segments and vertices
  plane.normal = (1.0 / norm(normal)) * normal;
  // The centroid, from the scaled offsets (a sum of the raw points may overflow).
  Point3 sum;
  for (const Point3& p : points) sum = sum + p;
  const Point3 centroid = (1.0 / static_cast<double>(points.size())) * sum;
  const Point3& first = input.points[facet.polygons[0][0]];
  plane.origin = first + Point3{centroid.x * unit, centroid.y * unit, centroid.z * unit};
  double scaled_distance = 0.0;
  for (const Point3& p : points) scaled_distance = std::max(scaled_distance, std::abs(dot(p - centroid, plane.normal)));
  plane.max_distance = scaled_distance * unit;
  // The widest triangle's height over the chord of length diameter / 2; the tolerance is the
  // tighter of the two, and the message names the measure it came from.
  const double width = 2.0 * norm(guide) / diameter;
  const bool thin = kWidthTolerance * width < kPlanarTolerance * diameter;
  const double tolerance = thin ? kWidthTolerance * width : kPlanarTolerance * diameter;
  char measure[80];
  std::snprintf(measure, sizeof measure, "facet %s %.3g, tolerance %.3g", thin ? "width" : "size",
                (thin ? width : diameter) * unit, tolerance * unit);
  if (scaled_distance > tolerance) {
    char text[200];
    std::snprintf(text, sizeof text, "not planar: a point lies %.3g from the best plane (%s)", plane.max_distance, measure);
    fail(input, f, text);
  }
  // A hole point is a point of the facet: one off its plane would be projected onto it silently,
  // carving wherever its shadow falls, so it is refused as a corner off the plane is.
  for (std::size_t h = 0; h < facet.holes.size(); ++h) {
    const Point3 d = facet.holes[h] - first;
    const Point3 scaled{std::ldexp(d.x, -std::ilogb(unit)), std::ldexp(d.y, -std::ilogb(unit)), std::ldexp(d.z, -std::ilogb(unit))};
    const double off = std::abs(dot(scaled - centroid, plane.normal));
    if (!(off <= tolerance)) {
      char text[200];
      std::snprintf(text, sizeof text, "hole %zu lies %.3g from the facet's plane (%s)", h + 1, off * unit, measure);
      const long line = h < facet.hole_lines.size() ? facet.hole_lines[h] : facet.line;
      throw InputError(input.source_name, line,
                       "facet " + std::to_string(f + static_cast<std::size_t>(input.first_index)) + ": " + text);
    }
  }
  // u along the first polygon's first edge of nonzero length, made orthogonal to the normal.
  Point3 edge;
  for (std::size_t i = 0; i < facet.polygons.size(); ++i)
    for (std::size_t k = 0; k + 1 < facet.polygons[i].size() && norm(edge) == 0.0; ++k)
      edge = points[polygon_start[i] + k + 1] - points[polygon_start[i] + k];
  if (norm(edge) == 0.0) edge = cross(plane.normal, Point3{1, 0, 0});
  if (norm(edge - dot(edge, plane.normal) * plane.normal) == 0.0) edge = cross(plane.normal, Point3{0, 1, 0});
  edge = edge - dot(edge, plane.normal) * plane.normal;
  plane.u = (1.0 / norm(edge)) * edge;
  plane.v = cross(plane.normal, plane.u);
  return plane;
}

}  // namespace deltri
