// Whether a vertex encroaches upon a subsegment (Shewchuk 2001, Appendix A and Sec. 6.4): whether it
// sees the subsegment at an angle of at least the rule's apex angle, 90 degrees for the diametral
// circle (Ruppert; -D), 180 - 2 theta for the diametral lens.
//
// One boundary rule for every encroachment test: "at least". A point on the boundary (on the diametral circle, or on
// a lens arc) encroaches, and so do a and b themselves upon the circle (their dot product is zero;
// a lens, whose arcs meet at a and b above 90 degrees, leaves them out). That is Appendix A's wording ("the angle at w is at
// least 90 degrees"), it is what conforming Delaunay needs (a vertex on a subsegment's diametral
// circle leaves the subsegment's Delaunay property degenerate), and it is the rule deltri's
// refinement has always applied, so its meshes did not change when the geometry was made one.
#pragma once

#include "geometry/point.h"
#include "geometry/predicates.h"

namespace deltri {

// The sign of (a - p) . (b - p), exactly (a floating-point filter, then expansion arithmetic, then
// integers outside the expansions' range): -1 strictly inside the circle with diameter ab, 0 on it
// (a and b included), +1 outside. Exact for every finite double.
int diametral_dot_sign(const Point& a, const Point& b, const Point& p);

// p strictly inside the circle with diameter ab: the free vertices Chew's step deletes before a
// subsegment is split (Fig. 39 l.40, refine/chew_step.cpp). Not an encroachment test: a
// vertex on the circle encroaches, but is not deleted. Deleting it too would change deltri's
// meshes (box.poly at -pa0.01: 70 deletions and 664 vertices instead of 62 and 659).
inline bool strictly_inside_diametral_circle(const Point& a, const Point& b, const Point& p) {
  return diametral_dot_sign(a, b, p) < 0;
}

// The region of a subsegment a vertex must enter to encroach upon it, as the apex angle it must
// see the subsegment at; made once per run, so no call converts an angle.
struct EncroachRule {
  double min_apex_angle_deg = 90.0;  // 90: the diametral circle; above 90: a lens
  double cos2_apex = 0.0;            // cos^2 of min_apex_angle_deg (for the lens arcs)
  // The diametral circle (-D, and -a alone in Ruppert's algorithm).
  static EncroachRule circle();
  // The diametral lens whose arcs meet the subsegment at theta (Sec. 6.4; 30 degrees gives an apex
  // of 120). theta >= 45 gives the circle: a lens is never wider than it. theta <= 0 gives only
  // the open subsegment itself.
  static EncroachRule lens(double theta_deg);
};

// Fig. 39 l.46/l.52: does p encroach upon subsegment ab, seeing it at an angle of at least the
// rule's apex angle? Exact for the circle, for points on the line through ab and for the side of
// the circle p is on; the lens arcs are irrational, so within a few ulps (relative) of an arc the
// answer is floating point (dot^2 >= cos^2(apex) |pa|^2 |pb|^2, in doubles).
bool encroaches(Predicates& pred, const Point& a, const Point& b, const Point& p, const EncroachRule& rule);

}  // namespace deltri
