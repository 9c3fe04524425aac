// The signs of the geometric determinants computed in integers, exact for every finite double.
//
// The expansion arithmetic of expansion.h is exact only while no product underflows (a product's
// roundoff below 2^-1074 is lost) and nothing overflows. Every finite double is m * 2^e exactly
// with integers m and e >= -1074, so after shifting all the coordinates of one test by their
// smallest exponent the determinant is a polynomial in plain integers, which this file evaluates
// with arbitrary-precision integers: slow (microseconds), but it can neither underflow nor
// overflow. The predicates call it only for coordinates outside the range where the expansions
// are proven exact (predicates.h), so ordinary inputs never reach it.
#pragma once

#include "geometry/point.h"

namespace deltri::exact_integer {

// Each returns -1, 0 or +1. The points must have finite coordinates.

// The sign of (a - c) x (b - c): +1 when a, b, c turn counter-clockwise.
int orient2d_sign(const Point& a, const Point& b, const Point& c);

// +1 when d is inside the circle through a, b, c given counter-clockwise.
int incircle_sign(const Point& a, const Point& b, const Point& c, const Point& d);

// The sign of (a - p) . (b - p): -1 exactly when p sees ab at an obtuse angle.
int dot_sign(const Point& a, const Point& b, const Point& p);

// True when every coordinate is zero or has magnitude in [2^low, 2^high]: the range check that
// sends the predicates here.
bool coordinates_within(const Point* points, int n, int low, int high);

}  // namespace deltri::exact_integer
