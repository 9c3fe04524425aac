#include "surface/facet_plane.h"

#include <cstdio>
#include <string>
#include <vector>

#include "pslg/errors.h"

namespace deltri {
namespace {

std::vector<Point3> facet_points(const FacetInput& input, const FacetInput::Facet& facet) {
  std::vector<Point3> points;
  for (const auto& polygon : facet.polygons)
    for (std::uint32_t v : polygon) points.push_back(input.points[v]);
  return points;
}

// Newell's normal of one closed polygon: twice its vector area, whatever its shape.
Point3 newell(const FacetInput& input, const std::vector<std::uint32_t>& polygon) {
  Point3 n;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Point3& a = input.points[polygon[i]];
    const Point3& b = input.points[polygon[(i + 1) % polygon.size()]];
    n = n + cross(a, b);
  }
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
  const std::vector<Point3> points = facet_points(input, facet);
  FacetPlane plane;
  const Point3 guide = spanning_normal(points, plane.diameter);
  // Collinear (or one point): no plane. The cross product of the widest pair is at least
  // diameter^2 * sin(angle), so this refuses angles below about 1e-12 radians.
  if (norm(guide) <= 1e-12 * plane.diameter * plane.diameter / 4 || plane.diameter == 0.0)
    fail(input, f, "its points are collinear, so it spans no plane");
  // The triangles wind about the normal as the facet's first loop does (outward, when the input's
  // loops are written so): its Newell normal, where it has one, sets the sign.
  Point3 sign = guide;
  for (const auto& polygon : facet.polygons)
    if (polygon.size() >= 3 && norm(newell(input, polygon)) > 1e-12 * norm(guide)) {
      sign = newell(input, polygon);
      break;
    }
  Point3 normal;
  for (const auto& polygon : facet.polygons) {
    if (polygon.size() < 3) continue;
    const Point3 n = newell(input, polygon);
    normal = dot(n, sign) >= 0.0 ? normal + n : normal - n;
  }
  if (norm(normal) <= 1e-12 * norm(guide)) normal = sign;  // only segments and vertices
  plane.normal = (1.0 / norm(normal)) * normal;
  Point3 sum;
  for (const Point3& p : points) sum = sum + p;
  plane.origin = (1.0 / static_cast<double>(points.size())) * sum;
  for (const Point3& p : points) plane.max_distance = std::max(plane.max_distance, std::abs(plane.distance(p)));
  if (plane.max_distance > kPlanarTolerance * plane.diameter) {
    char text[160];
    std::snprintf(text, sizeof text, "not planar: a point lies %.3g from the best plane (facet size %.3g, tolerance %.3g)",
                  plane.max_distance, plane.diameter, kPlanarTolerance * plane.diameter);
    fail(input, f, text);
  }
  // u along the first polygon's first edge of nonzero length, made orthogonal to the normal.
  Point3 edge;
  for (const auto& polygon : facet.polygons)
    for (std::size_t i = 0; i + 1 < polygon.size() && norm(edge) == 0.0; ++i)
      edge = input.points[polygon[i + 1]] - input.points[polygon[i]];
  if (norm(edge) == 0.0) edge = cross(plane.normal, Point3{1, 0, 0});
  if (norm(edge - dot(edge, plane.normal) * plane.normal) == 0.0) edge = cross(plane.normal, Point3{0, 1, 0});
  edge = edge - dot(edge, plane.normal) * plane.normal;
  plane.u = (1.0 / norm(edge)) * edge;
  plane.v = cross(plane.normal, plane.u);
  return plane;
}

}  // namespace deltri
