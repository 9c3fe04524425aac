// The representable points near a point, and shapes measured on them: refinement at the bottom of
// double precision (refine/bottom_scale.h) picks Steiner points among the doubles near the ideal
// one, since rounding the ideal point itself can ruin a triangle a few ulps across.
#pragma once

#include <vector>

#include "geometry/point.h"

namespace deltri {

// Every point (x, y) whose coordinates are at most `steps` doubles away from c.x and c.y (each axis
// on its own lattice: ulps differ between the axes and across powers of two), nearest first by
// the number of steps (Chebyshev distance in steps), c itself first. Appends (2 steps + 1)^2 points.
void lattice_neighbourhood(const Point& c, int steps, std::vector<Point>& out);

// The squared sine of the smallest angle of triangle a, b, c: (twice its area)^2 over the product
// of the squared lengths of the two longer sides; 0 if a, b, c are clockwise or collinear by the
// plain cross product. For points a few thousand ulps apart the coordinate differences, and their
// products, are exact, so the measure is as good as the exact angle for comparisons.
double smallest_angle_sine2(const Point& a, const Point& b, const Point& c);

// True when no double r to the left of p -> q makes a triangle p, q, r whose smallest angle has
// squared sine at least sin2_theta: then the triangles on edge pq can never meet the angle bound,
// whatever else is inserted (pq is the shortest edge at p and q, so Delaunay refinement keeps
// it). Such an r lies within |pq| / sin theta of p and q, so only the doubles in that box around
// the middle of pq are tried; false (not proven) when the box holds more than kHopelessSteps
// doubles on either side of the middle along an axis, or when sin2_theta is not positive.
inline constexpr int kHopelessSteps = 24;
bool hopeless_edge(const Point& p, const Point& q, double sin2_theta);

}  // namespace deltri
