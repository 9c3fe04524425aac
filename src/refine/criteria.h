// The quality criteria, the one place that says whether a triangle is bad, by how much and why:
// for refinement (Fig. 38 l.8, Fig. 39 l.42/l.54: an angle below theta, unless that angle separates
// two subsegments, which nothing can improve; too large for the user, delta(t); with --max-angle a
// largest angle above A, unless it lies between two subsegments), and for every report of the
// finished mesh (quality/bound_misses.h, -V, --json, --strict, the surface mode), which measure
// against the same bounds with a margin (BoundCheck). tests/refine/criteria_only_here.py fails
// when an angle is compared against a bound anywhere else.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "geometry/constructions.h"
#include "geometry/point.h"

#include "geometry/mesh_bounds.h"
#include "mesh/mesh.h"
#include "refine/area_field.h"
#include "refine/quality_queue.h"
#include "refine/size_test.h"

namespace deltri {

struct Criteria {
  AngleBound angle;  // its sin2() is the angle test; 0 turns it off
  SizeBounds size;   // triangle_bounds: also honour mesh.area_bound[t] when positive
  LargestAngleBound max_angle = {};  // --max-angle; not asked(): none
  // With bounds that vary within a region (-r with an .area file), the field gives each triangle
  // its bound instead of mesh.area_bound (refine/area_field.h); null or empty: not used.
  const AreaField* area_field = nullptr;
  const SizeTest* size_test = nullptr;  // a caller's test (refine/size_test.h), or null
};

// The area bound that applies to t (<= 0: none), as rules say: the field's at t's centroid when
// there is one, else mesh.area_bound[t]. Refinement ends by writing the field's into
// mesh.area_bound (refine.cpp), so the reports, which have no field, read the same bound.
double area_bound_of(const Mesh& mesh, TriangleId t, const Criteria& rules);

struct TriangleShape {
  EdgeRef shortest = kNone;  // the triangle's shortest edge
  double shortest_length2 = 0.0;
  // (r / B)^2 with r the circumradius-to-shortest-edge ratio and B = 1 / (2 sin theta); > 1 means
  // the smallest angle is below theta. Equals l1^2 l2^2 sin^2(theta) / (2 area)^2 with l1, l2
  // the two other edges, since r = l1 l2 l3 / (4 area).
  double ratio2_over_bound2 = 0.0;
  double area = 0.0;
  double length2[3] = {0.0, 0.0, 0.0};  // squared length of side i (corner i to corner i+1)
};

TriangleShape measure_triangle(const Mesh& mesh, TriangleId t, double sin2_theta);

// The doubles measure_triangle takes from corners a, b, c: the squared side lengths (side i from
// corner i to corner i + 1) and twice the signed area. Written once, so that surely_good's
// verdict is reached from the very doubles measure_triangle's is.
struct SideMeasures {
  double length2[3];
  double twice_area;
};
inline SideMeasures side_measures(const Point& a, const Point& b, const Point& c) {
  return {{squared_distance(a, b), squared_distance(b, c), squared_distance(c, a)},
          (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x)};
}
inline SideMeasures side_measures(const Mesh& mesh, TriangleId t) {
  const VertexId* c = mesh.corners_at(t);
  return side_measures(mesh.point(c[0]), mesh.point(c[1]), mesh.point(c[2]));
}

// The numerator of measure_triangle's (r / B)^2: the squared lengths of the two sides other than
// side s (the shortest), times sin^2 theta.
inline double ratio_numerator(const SideMeasures& m, unsigned s, double sin2_theta) {
  return m.length2[(s + 1) % 3] * m.length2[(s + 2) % 3] * sin2_theta;
}

// measure_triangle's (r / B)^2 from side measures m whose shortest side is s: HUGE_VAL for a flat
// or clockwise triangle.
inline double ratio2_over_bound2(const SideMeasures& m, unsigned s, double sin2_theta) {
  return m.twice_area > 0.0 ? ratio_numerator(m, s, sin2_theta) / (m.twice_area * m.twice_area) : HUGE_VAL;
}

// measure_triangle from t's side measures m, when the caller has them.
TriangleShape measure_triangle(TriangleId t, const SideMeasures& m, double sin2_theta);

// The two tests every verdict below makes: a ratio (r / B)^2 above the angle bound (exemptions
// aside), and an area above -a's bound.
inline bool above_ratio_bound(double ratio2_over_bound2, const AngleBound& angle) {
  return angle.sin2() > 0.0 && ratio2_over_bound2 > 1.0;
}
inline bool above_max_area(double area, const SizeBounds& size) { return size.max_area > 0.0 && area > size.max_area; }

// The side (0, 1, 2) with the least of the squared lengths len2, the first of tied ones: the edge
// whose Steiner point a triangle gets (measure_triangle, steiner_point_of).
inline unsigned shortest_side(const double len2[3]) {
  unsigned s = 0;
  if (len2[1] < len2[s]) s = 1;
  if (len2[2] < len2[s]) s = 2;
  return s;
}

// The side with the greatest squared length, the first of tied ones.
inline unsigned longest_side(const double len2[3]) {
  unsigned s = 0;
  if (len2[1] > len2[s]) s = 1;
  if (len2[2] > len2[s]) s = 2;
  return s;
}

struct Assessment {
  bool skinny = false;     // smallest angle below theta and not between two subsegments
  bool too_large = false;  // delta(t)
  bool too_obtuse = false; // largest angle above --max-angle and not between two subsegments
  bool bad() const { return skinny || too_large || too_obtuse; }
  TriangleShape shape;
  // A subsegment of a triangle beyond a small corner that is split instead of placing a point
  // (Terminator::beyond_corner_subsegment); kNone for every other triangle.
  EdgeRef split_instead = kNone;
};

// Fig. 38 l.8: "delta(t) or t has an angle less than theta (but not separating two subsegments)",
// or (--max-angle) an angle above A not separating two subsegments.
Assessment assess_triangle(const Mesh& mesh, TriangleId t, const Criteria& rules);
// The same from t's side measures m (side_measures), when the caller has them.
Assessment assess_triangle(const Mesh& mesh, TriangleId t, const Criteria& rules, const SideMeasures& m);

// Whether surely_good can answer for these rules: only the angle bound and -a's one area bound
// (no --max-angle, no per-triangle or field bounds, no -u edge length, no caller's size test).
inline bool has_quick_verdict(const Criteria& rules) {
  return !rules.max_angle.asked() && !rules.size.triangle_bounds && !(rules.size.max_edge_length > 0.0) &&
         rules.size_test == nullptr;
}

// A cheap "good" verdict on a triangle with side measures m, for rules with has_quick_verdict: true
// only where assess_triangle finds it neither skinny nor too large. Most triangles refinement makes are good, and this is a fifth
// of the full assessment's instructions. It is conservative by construction, with no margin to
// keep: measure_triangle's ratio is the rounded quotient x / y of the doubles x =
// ratio_numerator and y = twice_area^2 computed here, and x <= y makes that quotient at most 1
// (division rounds monotonically and 1 is a double), so not above the bound; area is 0.5
// twice_area as measure_triangle has it. Anything else (x > y, a flat or clockwise or non-finite
// triangle) says false and goes to the full assessment. The shell exemption and corner-lopping
// only ever clear a bad verdict, so they cannot turn this one.
inline bool surely_good(const SideMeasures& m, const Criteria& rules) {
  if (!(m.twice_area > 0.0)) return false;
  const double x = ratio_numerator(m, shortest_side(m.length2), rules.angle.sin2());
  if (!(x <= m.twice_area * m.twice_area)) return false;
  return !above_max_area(0.5 * m.twice_area, rules.size);
}

// assess_triangle's verdict as the queue of bad triangles needs it (Badness), for rules with
// has_quick_verdict and a triangle with side measures m no angle of which lies between two
// subsegments (at most one of its sides is one): true, with why set, where assess_triangle finds
// it bad. The same doubles in the same order, without an Assessment's other fields: refinement
// queues most of the triangles surely_good does not clear, and this is a fifth of the full assessment.
inline bool queue_badness(const SideMeasures& m, const Criteria& rules, Badness& why) {
  const unsigned s = shortest_side(m.length2);
  const double ratio = ratio2_over_bound2(m, s, rules.angle.sin2());
  why = {above_ratio_bound(ratio, rules.angle), ratio, m.length2[s]};
  return why.skinny || above_max_area(0.5 * m.twice_area, rules.size);
}

// How many times its size bounds t exceeds: area over the smallest area bound that applies, or
// (longest edge over the -u edge length) squared; at most 1 when t meets them.
double size_excess(const Mesh& mesh, TriangleId t, const TriangleShape& shape, const Criteria& rules);

// Whether a queue entry still names a triangle of the mesh: its slot is live and holds the three
// vertices the entry remembers (in any rotation). A slot reused or rewritten by a flip since holds
// other vertices, and the entry is stale (Fig. 38 l.12: "if t still exists").
bool is_current(const Mesh& mesh, const QueuedTriangle& entry);

// sin^2 of the smallest angle of triangle t.
double triangle_sine2(const Mesh& mesh, TriangleId t);

// True when the angle opposite edge e (at apex(e)) lies between two subsegments.
bool angle_between_subsegments(const Mesh& mesh, EdgeRef e);

// The squared sine of the smallest angle of triangle a, b, c: (twice its area)^2 over the product
// of the squared lengths of the two longer sides; 0 if a, b, c are clockwise or collinear by the
// plain cross product. For points a few thousand ulps apart the coordinate differences, and their
// products, are exact, so the measure is as good as the exact angle for comparisons.
// Inline, with the two longer sides' product as the largest of the three pairwise products (the
// same double: rounding is monotone), since the vertex-relocation search calls it in its inner loop.
inline double smallest_angle_sine2(const Point& a, const Point& b, const Point& c) {
  const double abx = b.x - a.x, aby = b.y - a.y, acx = c.x - a.x, acy = c.y - a.y;
  const double bcx = c.x - b.x, bcy = c.y - b.y;
  const double twice_area = abx * acy - aby * acx;
  if (!(twice_area > 0.0)) return 0.0;
  const double ab = abx * abx + aby * aby, bc = bcx * bcx + bcy * bcy, ca = acx * acx + acy * acy;
  return twice_area * twice_area / std::max({ab * bc, bc * ca, ca * ab});
}

// Whether a smallest-angle measure sine2 (smallest_angle_sine2) meets the bound whose sin2() is
// sin2_theta (at or above it), or falls below it. Not quite each other's negation: a NaN does neither.
inline bool meets_angle(double sine2, double sin2_theta) { return sine2 >= sin2_theta; }
inline bool below_angle(double sine2, double sin2_theta) { return sine2 < sin2_theta; }

// Whether a triangle measured against the bound measured_sin2 (its ratio2_over_bound2) is below the
// bound other_sin2 as well.
inline bool below_other_bound(const TriangleShape& shape, double measured_sin2, double other_sin2) {
  return shape.ratio2_over_bound2 * other_sin2 > measured_sin2;
}

// True when no double r to the left of p -> q makes a triangle p, q, r whose smallest angle has
// squared sine at least sin2_theta: then the triangles on edge pq can never meet the angle bound,
// whatever else is inserted (pq is the shortest edge at p and q, so Delaunay refinement keeps
// it). Such an r lies within |pq| / sin theta of p and q, so only the doubles in that box around
// the middle of pq are tried; false (not proven) when the box holds more than kHopelessSteps
// doubles on either side of the middle along an axis, or when sin2_theta is not positive.
inline constexpr int kHopelessSteps = 24;
bool hopeless_edge(const Point& p, const Point& q, double sin2_theta);

// The angle at a between rays to b and c, in degrees; atan2 stays accurate near 0 and 180
// degrees, where acos of a normalised dot product loses half the digits.
double angle_degrees(const Point& a, const Point& b, const Point& c);

// Whether the angle at p between rays to a and b exceeds bound A, decided exactly: a double filter,
// then expansion arithmetic (geometry/expansion.h) on the rare near ties. For A = 90, (a - p).(b - p)
// < 0 (geometry/encroachment.h). False when the bound is not asked.
bool angle_exceeds(const Point& p, const Point& a, const Point& b, const LargestAngleBound& bound);

// The corner (0, 1, 2) of triangle a, b, c whose angle exceeds the bound, or -1. At most one can.
int corner_above(const Point& a, const Point& b, const Point& c, const LargestAngleBound& bound);

// How well a would-be triangle a, b, c (counter-clockwise) meets both angle bounds: the lesser of
// sin^2 of its smallest angle less sin^2 theta and the cosine of its largest angle less cos A
// (either term left out when its bound is not asked); >= 0 when it meets both in doubles, < 0
// by how much it misses. A ranking for the choice of a Steiner point (obtuse_point.cpp), never the
// test of a triangle of the mesh, which is assess_triangle's.
double angle_margin(const Point& a, const Point& b, const Point& c, const AngleBound& angle,
                    const LargestAngleBound& max_angle);

// Whether -q implies the largest-angle bound: a triangle whose smallest angle is at least theta has
// none above 180 - 2 theta.
inline bool max_angle_implied(const LargestAngleBound& max_angle, const AngleBound& angle) {
  return !max_angle.asked() || max_angle.degrees() >= 180.0 - 2.0 * angle.degrees();
}

// Whether -q asks for more than reach_deg degrees (refinement past an algorithm's single-stage reach
// goes in two stages: refine/refine.cpp).
inline bool asks_beyond(const AngleBound& angle, double reach_deg) { return angle.degrees() > reach_deg; }

// Whether a surface triangle's smallest angle (in degrees, measured in space) is below -q's.
inline bool below_angle_bound(double smallest_degrees, const AngleBound& angle) {
  return angle.degrees() > 0.0 && smallest_degrees < angle.degrees();
}

// The criteria as the reports apply them to a finished mesh: measured in doubles with a relative
// margin of 1e-12, so that a triangle refinement judged good by the same bound in its own rounding
// is not counted for a last-bit difference. The largest angle is exact (angle_exceeds): the same
// answer refinement had. Its area bound is area_bound_of's, read from mesh.area_bound.
class BoundCheck {
 public:
  BoundCheck(const AngleBound& angle, const SizeBounds& size, const LargestAngleBound& max_angle);
  bool misses_angle(const Point& a, const Point& b, const Point& c) const;  // below -q
  bool misses_size(const Mesh& m, TriangleId t, const Point& a, const Point& b, const Point& c) const;
  int above_max_angle(const Point& a, const Point& b, const Point& c) const {  // corner_above
    return corner_above(a, b, c, max_angle_);
  }

 private:
  // -1 below the limit, +1 not below, 0 a near tie.
  int clear_side(const Point& a, const Point& b, const Point& c) const;
  bool below(const Point& a, const Point& b, const Point& c) const;
  bool clears_every_corner(const Point& a, const Point& b, const Point& c) const;
  double limit_ = 0.0;  // degrees; 0: no angle bound
  double tangent_ = 0.0;
  double clear_sine2_ = 0.0;  // sin^2 of the limit, raised by a relative 1e-6 (clears_every_corner)
  SizeBounds size_;
  LargestAngleBound max_angle_;
};

}  // namespace deltri
