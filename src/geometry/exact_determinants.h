// The geometric determinants evaluated exactly from the input coordinates, as expansions.
//
// These are the last resort of the adaptive predicates and the exact core of a few constructions.
// Every coordinate difference is first captured exactly as a two-component expansion (rounded
// difference plus roundoff), after which the polynomial is pure expansion arithmetic, so the result
// is exact whenever the expansion arithmetic is (see predicates.h for the coordinate range).
#pragma once

#include "geometry/point.h"

namespace deltri::exact {

// Output capacities, in doubles, of the routines below.
inline constexpr int kOrientMax = 16;
inline constexpr int kIncircleMax = 1536;
inline constexpr int kDotMax = 16;

// (a - c) x (b - c): positive when a, b, c turn counter-clockwise.
int orient2d(const Point& a, const Point& b, const Point& c, double* out);

// The lifted determinant of a, b, c relative to d: positive when d is inside the circle through
// a, b, c given counter-clockwise.
int incircle(const Point& a, const Point& b, const Point& c, const Point& d, double* out);

// (a - p) . (b - p): negative exactly when p sees ab at an obtuse angle.
int diametral_dot(const Point& a, const Point& b, const Point& p, double* out);

// orient2d rounded to a few ulps of its exact value, with the exact sign.
double orient2d_value(const Point& a, const Point& b, const Point& c);

}  // namespace deltri::exact
