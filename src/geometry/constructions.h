// Constructed points and measures of triangles and segments. Unlike the predicates these return
// rounded results; they are written to lose as little accuracy as doubles allow, but any decision
// the mesher takes about a constructed point must go through the exact predicates afterwards.
#pragma once

#include <algorithm>
#include <cmath>

#include "geometry/point.h"

namespace deltri {

// Centre of the circle through a, b, c. The triangle must not be degenerate (for collinear points
// the result is infinite or NaN).
Point circumcenter(const Point& a, const Point& b, const Point& c);

// Circumradius divided by the shortest edge length (1/sqrt(3) for an equilateral triangle, infinite
// for a degenerate one). Its square avoids the square root when only comparisons are needed.
double radius_edge_ratio(const Point& a, const Point& b, const Point& c);
double radius_edge_ratio_squared(const Point& a, const Point& b, const Point& c);

// Üngör's off-centre of triangle abc for the radius-edge bound beta (> 1/2, normally >= 1/sqrt(3)):
// the circumcentre if it is close enough to the shortest edge, otherwise the point on that edge's
// bisector whose triangle with the edge has radius-edge ratio exactly beta.
Point off_center(const Point& a, const Point& b, const Point& c, double beta);

// Where segments ab and cd cross; the caller guarantees that they do cross properly. The result is
// within a few ulps of the exact crossing and inside both segments' bounding boxes. For parallel
// segments it returns a.
Point segment_intersection(const Point& a, const Point& b, const Point& c, const Point& d);

// Signed area: positive when a, b, c are counter-clockwise. Plain floating point.
double triangle_area(const Point& a, const Point& b, const Point& c);

// Inline: the refinement's hot loops (cavity search, triangle shapes) call it for every vertex.
inline double squared_distance(const Point& a, const Point& b) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  return dx * dx + dy * dy;
}

// The larger magnitude of p's coordinates: the scale of the doubles where p lies (its ulp is
// about 2^-52 of this).
inline double magnitude(const Point& p) { return std::max(std::fabs(p.x), std::fabs(p.y)); }

// n units in the last place (2^-52 relative) of coordinates of magnitude `scale`.
inline double ulps_at(double scale, double n) { return n * 0x1p-52 * scale; }

}  // namespace deltri
