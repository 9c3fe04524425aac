// Is a subsegment encroached? Shewchuk 2001, Appendix A and Fig. 41: in a constrained Delaunay
// triangulation only the one or two apices opposite a subsegment need testing, because any
// visible vertex inside its diametral circle or lens would sit inside one of those triangles'
// circumcircles.
#pragma once

#include "geometry/point.h"
#include "geometry/predicates.h"
#include "mesh/mesh.h"

namespace deltri {

// What region of a subsegment xy a vertex w must enter to encroach upon it, as the apex angle
// at w: w encroaches when angle(x, w, y) >= min_apex_angle.
struct EncroachRule {
  // 90 degrees: the diametral circle (Ruppert; -D). 180 - 2 theta: the diametral lens (Sec. 6.4,
  // there with theta = 30 giving 120 degrees), never wider than the circle.
  double min_apex_angle_deg = 90.0;
};

EncroachRule diametral_circle_rule();
// Lens whose arcs meet the subsegment at angle theta; theta >= 45 degrees gives the circle.
EncroachRule diametral_lens_rule(double theta_deg);

// Fig. 39 l.46/l.52: does w encroach upon subsegment xy? Exact for the circle and for points on
// the subsegment; the lens boundary is irrational, so near it the answer is floating point.
bool encroaches(Predicates& pred, const Point& x, const Point& y, const Point& w,
                const EncroachRule& rule);

// Fig. 38 l.4: is the subsegment on edge e encroached by the apex on either side?
bool is_encroached(const Mesh& mesh, Predicates& pred, EdgeRef e, const EncroachRule& rule);

}  // namespace deltri
