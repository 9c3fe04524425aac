// A caller's test of whether a triangle is too big (Triangle's -u triunsuitable, MeshPy's
// refinement_func): given the corners, counter-clockwise, and the area, true means "split it".
// Refinement asks it of every triangle it assesses, from one thread at a time, alongside the -q,
// -a and -u bounds (a triangle is split when any of them says so).
#pragma once

#include <algorithm>
#include <functional>

#include "geometry/point.h"

namespace deltri {

using SizeTest = std::function<bool(const Point& org, const Point& dest, const Point& apex, double area)>;

// Triangle 1.6's stock triunsuitable, what its bare -u runs: a triangle is too big when its longest
// edge squared exceeds 0.05 (x^2 + y^2) + 0.02 at its origin vertex (x, y). Which corner Triangle
// calls the origin depends on how it holds the triangle at that moment; deltri takes the corner
// farthest from (0, 0), so the answer does not depend on orientation: a triangle is split only
// when the test fails at all three corners, and every triangle left passes it at one corner at
// least, as every triangle of Triangle's own -u mesh does.
inline bool stock_size_test(const Point& a, const Point& b, const Point& c, double) {
  const auto d2 = [](const Point& p, const Point& q) { return (p.x - q.x) * (p.x - q.x) + (p.y - q.y) * (p.y - q.y); };
  const auto r2 = [](const Point& p) { return p.x * p.x + p.y * p.y; };
  const double longest = std::max({d2(a, b), d2(b, c), d2(c, a)});
  return longest > 0.05 * std::max({r2(a), r2(b), r2(c)}) + 0.02;
}

}  // namespace deltri
