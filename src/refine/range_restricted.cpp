#include "refine/range_restricted.h"

#include <cmath>
#include <numbers>

namespace deltri {
namespace {

constexpr double kSlack = 1e-9;
// The paper's epsilon: c1 just below a range's top, "the largest floating-point number less than"
// it in exact arithmetic; a relative 2^-40 stays below it after the split point is rounded.
constexpr double kBelow = 1.0 - 0x1p-40;

struct Mantissa {
  double c;     // in [1, 2)
  double unit;  // 2^x
};

Mantissa mantissa_of(double length) {
  int exponent = 0;
  const double fraction = std::frexp(length, &exponent);  // in [0.5, 1)
  return {2.0 * fraction, std::ldexp(1.0, exponent - 1)};
}

}  // namespace

double legal_range_top(bool lenses) { return lenses ? std::numbers::sqrt3 : std::numbers::sqrt2; }

bool legal_length(double length, double top) {
  const double c = mantissa_of(length).c;
  return c < top * (1.0 + kSlack) || c > 2.0 * (1.0 - kSlack);
}

// Sec. 7.3's recipes for an illegal c in [top, 2): with sqrt(2), c1 = sqrt(2)/4 - eps below 3/2,
// 1 below 1 + sqrt(2)/2, sqrt(2)/2 - eps above; with sqrt(3), 1 below 1 + sqrt(3)/2, sqrt(3)/2 - eps
// above. c2 = c - c1 is then legal too.
double range_restricted_first_piece(double length, double top) {
  if (legal_length(length, top)) return 0.5 * length;
  const Mantissa m = mantissa_of(length);
  double c1 = 1.0;
  if (m.c >= 1.0 + 0.5 * top) c1 = 0.5 * top * kBelow;
  else if (top < 1.5 && m.c < 1.5) c1 = 0.25 * top * kBelow;
  return c1 * m.unit;
}

Point range_restricted_split_point(const Point& a, const Point& b, double top) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double length = std::sqrt(dx * dx + dy * dy);
  if (!std::isfinite(length) || length == 0.0) return Point{0.5 * a.x + 0.5 * b.x, 0.5 * a.y + 0.5 * b.y};
  const double t = range_restricted_first_piece(length, top) / length;
  return Point{a.x + t * dx, a.y + t * dy};
}

}  // namespace deltri
