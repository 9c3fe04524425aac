// Range-restricted segment splitting (Shewchuk 2001, Sec. 7.3, Fig. 36), a split-point policy of
// Fig. 39 l.39. Subsegment lengths are kept, where possible, of the form c 2^x with c in [1, top)
// and x an integer, the unit being the coordinate unit (the one the concentric shells of Sec. 6.2
// measure their power-of-two radii in). A legal subsegment is bisected (its halves are legal); an
// illegal one is split once, unevenly, by the paper's recipe, so that both pieces are legal. top is
// sqrt(3) with diametral lenses (the Ruppert-Chew hybrid, deltri's default Terminator: the illegal
// ranges need a geometric width of only 2/sqrt(3)) and sqrt(2) with diametral circles (-D).
// Shell splits keep their priority (Terminator::plan_split): they cut cluster subsegments to
// powers of two, which are legal.
#pragma once

#include "geometry/point.h"

namespace deltri {

// The top of the legal mantissa range: sqrt(3) with lenses, sqrt(2) with diametral circles.
double legal_range_top(bool lenses);

// Whether length is c 2^x with c in [1, top), allowing a relative slack of 1e-9 at the range's ends
// for the rounding of split points.
bool legal_length(double length, double top);

// The length of the piece measured from the first end: half of a legal length, the paper's c1 2^x
// for an illegal one.
double range_restricted_first_piece(double length, double top);

// The split point of subsegment ab under the policy (the first piece measured from a).
Point range_restricted_split_point(const Point& a, const Point& b, double top);

}  // namespace deltri
