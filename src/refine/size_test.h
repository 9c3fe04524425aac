// A caller's test of whether a triangle is too big (Triangle's -u triunsuitable, MeshPy's
// refinement_func): given the corners, counter-clockwise, and the area, true means "split it".
// Refinement asks it of every triangle it assesses, from one thread at a time, alongside the -q,
// -a and -u bounds (a triangle is split when any of them says so).
#pragma once

#include <functional>

#include "geometry/point.h"

namespace deltri {

using SizeTest = std::function<bool(const Point& org, const Point& dest, const Point& apex, double area)>;

}  // namespace deltri
