// The representable points near a point: refinement at the bottom of double precision
// (refine/bottom_scale.h) picks Steiner points among the doubles near the ideal one, since rounding
// the ideal point itself can ruin a triangle a few ulps across. The shapes measured on them, and
// the edges no double can give a good triangle, are the criteria's (refine/criteria.h).
#pragma once

#include <vector>

#include "geometry/point.h"

namespace deltri {

// Every point (x, y) whose coordinates are at most `steps` doubles away from c.x and c.y (each axis
// on its own lattice: ulps differ between the axes and across powers of two), nearest first by
// the number of steps (Chebyshev distance in steps), c itself first. Appends (2 steps + 1)^2 points.
void lattice_neighbourhood(const Point& c, int steps, std::vector<Point>& out);

// The doubles within `radius` of x, x itself included, into out, if there are at most `limit` on
// each side of x; false otherwise.
bool doubles_within(double x, double radius, int limit, std::vector<double>& out);

}  // namespace deltri
