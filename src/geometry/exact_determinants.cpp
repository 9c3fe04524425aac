#include "geometry/exact_determinants.h"

#include "geometry/expansion.h"

namespace deltri::exact {
namespace {

using namespace deltri::expansion;

// A short expansion held by value; the sizes here never exceed 16 components.
struct Short {
  double c[16];
  int n = 0;
};

Short difference(double a, double b) {
  Short d;
  double rounded, tail;
  two_diff(a, b, rounded, tail);
  if (tail != 0.0) d.c[d.n++] = tail;
  if (rounded != 0.0) d.c[d.n++] = rounded;
  return d;
}

// Product of two expansions of at most two components each (at most 8 components).
Short product(const Short& e, const Short& f) {
  Short p;
  double scratch[2 * 2 * 3];
  p.n = multiply(e.c, e.n, f.c, f.n, p.c, scratch);
  return p;
}

// e * f - g * h for two-component factors (at most 16 components).
Short cross(const Short& e, const Short& f, const Short& g, const Short& h) {
  Short left = product(e, f);
  Short right = product(g, h);
  negate(right.c, right.n);
  Short result;
  result.n = sum(left.c, left.n, right.c, right.n, result.c);
  return result;
}

Short lift(const Short& dx, const Short& dy) {
  const Short xx = product(dx, dx);
  const Short yy = product(dy, dy);
  Short result;
  result.n = sum(xx.c, xx.n, yy.c, yy.n, result.c);
  return result;
}

// lift * minor, both at most 16 components, into out (at most 512 components).
int lifted_term(const Short& lifted, const Short& minor, double* out) {
  double scratch[2 * 16 * 17];
  return multiply(minor.c, minor.n, lifted.c, lifted.n, out, scratch);
}

}  // namespace

int orient2d(const Point& a, const Point& b, const Point& c, double* out) {
  const Short acx = difference(a.x, c.x), acy = difference(a.y, c.y);
  const Short bcx = difference(b.x, c.x), bcy = difference(b.y, c.y);
  const Short det = cross(acx, bcy, acy, bcx);
  for (int i = 0; i < det.n; ++i) out[i] = det.c[i];
  return det.n;
}

int incircle(const Point& a, const Point& b, const Point& c, const Point& d, double* out) {
  const Short adx = difference(a.x, d.x), ady = difference(a.y, d.y);
  const Short bdx = difference(b.x, d.x), bdy = difference(b.y, d.y);
  const Short cdx = difference(c.x, d.x), cdy = difference(c.y, d.y);
  double a_term[512], b_term[512], c_term[512], ab[1024];
  const int an = lifted_term(lift(adx, ady), cross(bdx, cdy, cdx, bdy), a_term);
  const int bn = lifted_term(lift(bdx, bdy), cross(cdx, ady, adx, cdy), b_term);
  const int cn = lifted_term(lift(cdx, cdy), cross(adx, bdy, bdx, ady), c_term);
  const int abn = sum(a_term, an, b_term, bn, ab);
  return sum(ab, abn, c_term, cn, out);
}

int diametral_dot(const Point& a, const Point& b, const Point& p, double* out) {
  const Short apx = difference(a.x, p.x), apy = difference(a.y, p.y);
  const Short bpx = difference(b.x, p.x), bpy = difference(b.y, p.y);
  const Short xx = product(apx, bpx);
  const Short yy = product(apy, bpy);
  return sum(xx.c, xx.n, yy.c, yy.n, out);
}

double orient2d_value(const Point& a, const Point& b, const Point& c) {
  double det[kOrientMax];
  const int n = orient2d(a, b, c, det);
  return signed_estimate(det, n);
}

}  // namespace deltri::exact
