// Refinement at the bottom of double precision: inputs whose vertices are an ulp or two apart
// (robustness tests of other triangulators) need triangles a few ulps across. There the ideal
// Steiner point is still computed accurately (relative to a corner), but rounding it to doubles
// moves it by up to half an ulp in each coordinate, which at that scale can turn a good triangle
// into a sliver, or leave the bad one as it was. Below kBottomScaleUlps the Terminator therefore:
//  - refuses a triangle at once if no double can make a good triangle with its shortest edge
//    (hopeless_edge, geometry/lattice.h);
//  - otherwise tries the doubles near the ideal point (lattice_neighbourhood) and inserts the one
//    whose new triangles are best, those up to twice t's shortest edge first, among the points
//    whose cavity holds t, whose insertion radius is at least kBottomRadius2 (squared) of t's
//    shortest edge (so no shorter scale is started), and whose new triangles with an edge no
//    longer than t's shortest are good, better than t, or no worse than the triangle they replace
//    on that edge; if there is none, no point is inserted for t (the rounded ideal point may
//    still ask for the subsegments it encroaches upon to be split; otherwise it is a guard
//    refusal), so a triangle that no nearby double improves does not start a cascade;
//  - splits a subsegment at the double near its midpoint closest to the line of its segment piece
//    that keeps the triangles beside it counter-clockwise (bottom_scale_split), which is also
//    tried at any scale when the rounded midpoint fails (a neighbour flush with the subsegment),
//    before the subsegment is locked.
// Ordinary meshes never get there: Terminator::bottom_possible_ is false when the feature floor
// is above the bottom scale everywhere, and then this costs one comparison per split.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "geometry/constructions.h"
#include "geometry/point.h"
#include "mesh/mesh.h"

namespace deltri {

inline constexpr double kBottomScaleUlps = 64.0;
// How far from the ideal point the search goes, in steps of each axis's lattice.
inline constexpr int kBottomScaleSteps = 2;
// The shortest edge a bottom-scale insertion may make, squared, relative to the bad triangle's
// shortest edge: (1/sqrt 2)^2, the legs of a right isosceles triangle on it.
inline constexpr double kBottomRadius2 = 0.5;

// Is an edge of squared length `length2` at p shorter than kBottomScaleUlps units in the last
// place of p's larger coordinate (within a factor of two)?
inline bool at_bottom_scale(double length2, const Point& p) {
  const double bottom = ulps_at(magnitude(p), kBottomScaleUlps);
  return length2 < bottom * bottom;
}

// The edges of `mesh` at the bottom scale that no double can give a triangle with angles of at
// least theta (sin2_theta = sin^2 theta; 0 counts none). With `threads` 2 or more, a large mesh's
// two halves of the edges are counted at once.
std::uint64_t count_hopeless_edges(const Mesh& mesh, double sin2_theta, int threads = 1);

}  // namespace deltri
