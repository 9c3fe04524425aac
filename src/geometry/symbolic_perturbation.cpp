// The tie rule of Predicates::incircle_perturbed: a symbolic perturbation of the lifting map
// (after Edelsbrunner and Muecke's "simulation of simplicity", applied to the lifts only).
//
// incircle(a, b, c, d) is the determinant of the rows (p - d, z_p - z_d) for p = a, b, c, where
// z_p = x_p^2 + y_p^2 is p's lift: the lift column is the rows' |p - d|^2 less a combination of the
// first two columns. The determinant is affine in the lifts, with
//   d det / d z_a = orient(b, c, d),  d det / d z_b = orient(c, a, d),
//   d det / d z_c = orient(a, b, d),  d det / d z_d = -orient(a, b, c).
// Lowering each lift z_p by epsilon^rank(p) therefore adds -sum epsilon^rank(p) * (d det / d z_p),
// a polynomial in epsilon whose sign for an infinitesimal epsilon is that of its lowest-order
// nonzero term: minus the derivative of the highest-priority point whose derivative is not zero.
// The derivatives are exact orientations, so this is exact too.
//
// With the lifts perturbed no four points with a proper triangle among them are co-planar once
// lifted, so the lower convex hull of the lifted points, the Delaunay triangulation of the
// perturbed points, is a unique triangulation; it is also a Delaunay triangulation of the points
// themselves (the perturbation only decides exact ties). Every point stays on the lower hull
// (epsilon is infinitesimal), so the vertices and the convex hull edges do not change.
//
// Only the first term is ever needed: four distinct points with a zero determinant lie on one
// circle (then no three are collinear, and every derivative is nonzero) or on one line (then every
// derivative is zero). So the tie costs a search for the smallest point and one orientation.
#include "geometry/predicates.h"

namespace deltri {

double Predicates::incircle_adapt_perturbed(const Point& a, const Point& b, const Point& c, const Point& d,
                                            double permanent) {
  const double det = incircle_adapt(a, b, c, d, permanent);
  if (det != 0.0) return det;
  const Point* points[4] = {&a, &b, &c, &d};
  int first = 0;  // the highest priority: smallest x, then smallest y
  for (int k = 1; k < 4; ++k) {
    const Point &p = *points[k], &q = *points[first];
    if (p.x < q.x || (p.x == q.x && p.y < q.y)) first = k;
  }
  double derivative = 0.0;
  switch (first) {
    case 0: derivative = orient2d(b, c, d); break;
    case 1: derivative = orient2d(c, a, d); break;
    case 2: derivative = orient2d(a, b, d); break;
    default: derivative = -orient2d(a, b, c); break;
  }
  if (derivative == 0.0) return 0.0;  // all four collinear
  return derivative > 0.0 ? -1.0 : 1.0;
}

}  // namespace deltri
