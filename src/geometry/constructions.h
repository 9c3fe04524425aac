// Constructed points and measures of triangles and segments. Unlike the predicates these return
// rounded results; they are written to lose as little accuracy as doubles allow, but any decision
// the mesher takes about a constructed point must go through the exact predicates afterwards.
#pragma once

#include <algorithm>
#include <cmath>

#include "geometry/point.h"

namespace deltri {

// Centre of the circle through a, b, c, to nearly full accuracy even for a thin triangle (its
// denominator is exact when the floating-point cross product cancels): the Voronoi vertices deltri
// writes (-v). The triangle must not be degenerate (for collinear points the result is infinite
// or NaN).
Point circumcenter(const Point& a, const Point& b, const Point& c);

// How far p lies inside the circle through a, b, c: a lower bound on R - |p - o| (centre o, radius
// R) that allows for the rounding of the construction, scaled by how flat the triangle is and by
// the coordinates' magnitude; 0 or less when p may be outside, -inf for a flat triangle. Every
// vertex a constrained Delaunay triangulation shows to the inside of a triangle lies outside its
// circle, so a point in a triangle is at least this far from each of them (a subsegment split's
// insertion radius, Terminator::plan_split).
double depth_in_circumcircle(const Point& a, const Point& b, const Point& c, const Point& p);

// Where Delaunay refinement splits a bad triangle pqr whose shortest edge is pq (Fig. 38 l.13):
// Ungor's off-centre, the point on pq's bisector, on the side of r, at height factor |pq| above
// pq's midpoint, when that is nearer the edge than the circumcentre; otherwise the circumcentre.
// factor is AngleBound::off_center_factor(), 0.475 cot(theta / 2) (geometry/mesh_bounds.h): the
// new triangle on pq then has an apex angle a little above theta. factor <= 0 gives the
// circumcentre. The circumcentre here is the plain quotient of floating-point determinants taken
// relative to p, not circumcenter()'s: the refinement probes the point exactly before inserting
// it (refine/candidate_probe.h), and every mesh deltri makes depends on these bits. pqr must not
// be flat (the result is then infinite or NaN).
Point off_center(const Point& p, const Point& q, const Point& r, double factor);

// Where segments ab and cd cross; the caller guarantees that they do cross properly. The result is
// within a few ulps of the exact crossing and inside both segments' bounding boxes. For parallel
// segments it returns a.
Point segment_intersection(const Point& a, const Point& b, const Point& c, const Point& d);

// Where segment ab crosses the circle of centre o and radius `radius`: writes 0, 1 or 2 points
// to out (in order from a) and returns how many. Plain floating point: the locally optimal Steiner
// points (refine/steiner_point.h) use the crossings as candidates and check each one afterwards.
int segment_circle_crossings(const Point& a, const Point& b, const Point& o, double radius, Point out[2]);

// Where segment ab crosses segment cd, in plain floating point; false when they are parallel or
// do not cross. For candidates that are checked afterwards, as above; segment_intersection is the
// accurate one.
bool segment_crossing(const Point& a, const Point& b, const Point& c, const Point& d, Point& out);

// Signed area: positive when a, b, c are counter-clockwise. Plain floating point.
double triangle_area(const Point& a, const Point& b, const Point& c);

// The midpoint of ab, halves of the sums (the same double whichever of a and b comes first).
inline Point midpoint(const Point& a, const Point& b) { return {0.5 * (a.x + b.x), 0.5 * (a.y + b.y)}; }

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
