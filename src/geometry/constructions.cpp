#include "geometry/constructions.h"

#include <algorithm>
#include <cmath>

#include "geometry/exact_determinants.h"
#include "geometry/expansion.h"

namespace deltri {
namespace {

// (b - a) x (c - a) to nearly full relative accuracy. The floating-point value is kept when the
// subtraction cancelled fewer than about 10 bits (relative error then below 1e-12); a thinner
// triangle gets the exact determinant, because the circumcentre of a thin triangle is only as good
// as this denominator.
double accurate_cross(const Point& a, const Point& b, const Point& c) {
  const double left = (b.x - a.x) * (c.y - a.y);
  const double right = (b.y - a.y) * (c.x - a.x);
  const double cross = left - right;
  if (std::fabs(cross) >= 0x1p-10 * (std::fabs(left) + std::fabs(right))) return cross;
  return exact::orient2d_value(a, b, c);
}

// Clamping to the overlap of the two ranges cannot move a correct answer and keeps a rounded one
// from leaving either segment.
double clamp_to_both(double value, double a, double b, double c, double d) {
  const double lo = std::max(std::min(a, b), std::min(c, d));
  const double hi = std::min(std::max(a, b), std::max(c, d));
  return lo <= hi ? std::clamp(value, lo, hi) : value;
}

// (o1 * v_b - o2 * v_a) / (o1 - o2) with the numerator and denominator exact until the division:
// the coordinate of the point where orient2d(c, d, .), affine along ab, vanishes.
double crossing_coordinate(const double* o1, int n1, const double* o2, int n2, double v_a,
                           double v_b, double denominator) {
  double first[2 * exact::kOrientMax], second[2 * exact::kOrientMax];
  double numerator[4 * exact::kOrientMax];
  const int first_len = expansion::scale(o1, n1, v_b, first);
  const int second_len = expansion::scale(o2, n2, v_a, second);
  expansion::negate(second, second_len);
  const int len = expansion::sum(first, first_len, second, second_len, numerator);
  return expansion::estimate(numerator, len) / denominator;
}

}  // namespace

Point circumcenter(const Point& a, const Point& b, const Point& c) {
  // Working relative to a keeps the squared lengths small when the triangle is far from the origin.
  const double bx = b.x - a.x, by = b.y - a.y;
  const double cx = c.x - a.x, cy = c.y - a.y;
  const double b_len2 = bx * bx + by * by;
  const double c_len2 = cx * cx + cy * cy;
  const double inverse = 0.5 / accurate_cross(a, b, c);
  return {a.x + (cy * b_len2 - by * c_len2) * inverse, a.y + (bx * c_len2 - cx * b_len2) * inverse};
}

// The slack is a generous multiple of the rounding analysis: o - a is two determinants over the
// cross product, each off by a few ulps of its terms, so its error is a few ulps of the longest
// edge times longest^2 / |cross| (the inverse sine of an angle); the differences from a and the
// final additions add a few ulps of the coordinates.
double depth_in_circumcircle(const Point& a, const Point& b, const Point& c, const Point& p) {
  const double bx = b.x - a.x, by = b.y - a.y, cx = c.x - a.x, cy = c.y - a.y;
  const double b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
  const double cross = bx * cy - by * cx;
  const double ox = (cy * b2 - by * c2) / (2.0 * cross), oy = (bx * c2 - cx * b2) / (2.0 * cross);  // o - a
  const double radius = std::sqrt(ox * ox + oy * oy);
  const double px = (p.x - a.x) - ox, py = (p.y - a.y) - oy;
  const double off = std::sqrt(px * px + py * py);
  const double longest2 = std::max({b2, c2, (cx - bx) * (cx - bx) + (cy - by) * (cy - by)});
  const double flatness = 2.0 * longest2 / std::fabs(cross);
  const double magnitude = std::max({std::fabs(a.x), std::fabs(a.y), std::fabs(p.x), std::fabs(p.y)});
  constexpr double kSlackUlps = 64.0 * 0x1p-52;
  const double slack = kSlackUlps * (flatness * (std::sqrt(longest2) + radius + off) + magnitude);
  const double depth = radius - off - slack;
  return std::isfinite(depth) ? depth : -HUGE_VAL;
}

Point off_center(const Point& p, const Point& q, const Point& r, double factor) {
  const double bx = q.x - p.x, by = q.y - p.y, cx = r.x - p.x, cy = r.y - p.y;
  const double b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
  const double denominator = 2.0 * (bx * cy - by * cx);
  const Point centre{p.x + (cy * b2 - by * c2) / denominator, p.y + (bx * c2 - cx * b2) / denominator};
  if (factor <= 0.0) return centre;
  // The circumcentre lies on pq's bisector, on r's side when the angle at r is acute (the smallest
  // angle is), so the off-centre is the point at the wanted height on the way to it.
  const Point mid = midpoint(p, q);
  const double dx = centre.x - mid.x, dy = centre.y - mid.y;
  const double to_centre = std::sqrt(dx * dx + dy * dy);
  const double height = factor * std::sqrt(b2);
  if (!(height < to_centre)) return centre;
  const double s = height / to_centre;
  return Point{mid.x + s * dx, mid.y + s * dy};
}

namespace {

Point intersection_in_range(const Point& a, const Point& b, const Point& c, const Point& d);

// The exponent k (a power of two) that brings the largest coordinate of the four points near 1.
int normalizing_exponent(const Point& a, const Point& b, const Point& c, const Point& d) {
  const double largest = std::max({magnitude(a), magnitude(b), magnitude(c), magnitude(d)});
  int e = 0;
  std::frexp(largest, &e);
  return -e;
}

Point scaled(const Point& p, int k) { return {std::ldexp(p.x, k), std::ldexp(p.y, k)}; }

}  // namespace

Point segment_intersection(const Point& a, const Point& b, const Point& c, const Point& d) {
  // The expansions below are exact only while their products neither overflow nor underflow.
  // The crossing is affine-invariant, so far from 1 it is found for the four points scaled by a
  // power of two that brings the largest coordinate near 1, and scaled back. Scaling up is
  // exact; scaling down loses only bits below 2^-1074 of the largest coordinate, far below the
  // final rounding of the crossing. The result is clamped to both boxes as always.
  const double largest = std::max({magnitude(a), magnitude(b), magnitude(c), magnitude(d)});
  if (largest > 0x1p100 || (largest > 0.0 && largest < 0x1p-100)) {
    const int k = normalizing_exponent(a, b, c, d);
    const Point p = scaled(intersection_in_range(scaled(a, k), scaled(b, k), scaled(c, k), scaled(d, k)), -k);
    return {clamp_to_both(p.x, a.x, b.x, c.x, d.x), clamp_to_both(p.y, a.y, b.y, c.y, d.y)};
  }
  return intersection_in_range(a, b, c, d);
}

namespace {

Point intersection_in_range(const Point& a, const Point& b, const Point& c, const Point& d) {
  // orient2d(c, d, .) is affine along ab, with exact values o1 at a and o2 at b, so the crossing is
  // (o1 b - o2 a) / (o1 - o2). Evaluating numerator and denominator exactly leaves only the final
  // rounding and division: a few ulps, however long or far from the origin the segments are.
  // The numerator has degree three in the coordinates: segment_intersection keeps them near 1.
  double o1[exact::kOrientMax], o2[exact::kOrientMax], difference[2 * exact::kOrientMax];
  const int n1 = exact::orient2d(c, d, a, o1);
  int n2 = exact::orient2d(c, d, b, o2);
  expansion::negate(o2, n2);
  const int dn = expansion::sum(o1, n1, o2, n2, difference);
  expansion::negate(o2, n2);
  if (expansion::sign(difference, dn) == 0) return a;
  const double denominator = expansion::estimate(difference, dn);
  const double x = crossing_coordinate(o1, n1, o2, n2, a.x, b.x, denominator);
  const double y = crossing_coordinate(o1, n1, o2, n2, a.y, b.y, denominator);
  return {clamp_to_both(x, a.x, b.x, c.x, d.x), clamp_to_both(y, a.y, b.y, c.y, d.y)};
}

}  // namespace

int segment_circle_crossings(const Point& a, const Point& b, const Point& o, double radius, Point out[2]) {
  // |a + t (b - a) - o|^2 = radius^2, a quadratic in t; the crossings are its roots in [0, 1].
  const double dx = b.x - a.x, dy = b.y - a.y, fx = a.x - o.x, fy = a.y - o.y;
  const double qa = dx * dx + dy * dy, qb = 2.0 * (fx * dx + fy * dy), qc = fx * fx + fy * fy - radius * radius;
  const double discriminant = qb * qb - 4.0 * qa * qc;
  if (!(qa > 0.0) || !(discriminant >= 0.0)) return 0;
  const double root = std::sqrt(discriminant);
  int n = 0;
  for (const double t : {(-qb - root) / (2.0 * qa), (-qb + root) / (2.0 * qa)})
    if (t >= 0.0 && t <= 1.0) out[n++] = Point{a.x + t * dx, a.y + t * dy};
  return n;
}

bool segment_crossing(const Point& a, const Point& b, const Point& c, const Point& d, Point& out) {
  const double rx = b.x - a.x, ry = b.y - a.y, sx = d.x - c.x, sy = d.y - c.y;
  const double denominator = rx * sy - ry * sx;
  if (!(std::fabs(denominator) > 0.0)) return false;
  const double qx = c.x - a.x, qy = c.y - a.y;
  const double t = (qx * sy - qy * sx) / denominator, u = (qx * ry - qy * rx) / denominator;
  if (!(t >= 0.0 && t <= 1.0 && u >= 0.0 && u <= 1.0)) return false;
  out = Point{a.x + t * rx, a.y + t * ry};
  return true;
}

double triangle_area(const Point& a, const Point& b, const Point& c) {
  return 0.5 * ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
}

}  // namespace deltri
