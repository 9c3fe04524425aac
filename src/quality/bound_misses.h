// Which triangles of the final mesh miss the requested bounds, and why: an account a solver's
// user can trust, computed from the output mesh alone (not from what refinement believes), so a
// triangle refinement exempted or gave up on is counted all the same.
//
// A triangle misses the bounds when its smallest angle is below the -q angle, its largest angle is
// above the --max-angle bound, its area is above the -a bound (or its own regional / .area bound),
// or its longest edge is above the -u length; each measured by the criteria (refine/criteria.h,
// BoundCheck).
// Each such triangle gets the first of these causes that applies (docs/manual.md, "Quality
// accounting"):
//   small_input_angle  it misses no size bound, and its angle miss (below -q, or above --max-angle
//                      without lying between two segments) is explained by the input, at a vertex
//                      j where input segments meet at an input angle phi under 60 degrees: an input
//                      vertex, or a vertex deltri made where two input segments cross (every mesh
//                      that keeps the segments has a vertex there, with the angles they cross at):
//                      (1) a corner j, with the other two corners inside the sector between two
//                      neighbouring segments at j, that sector under 60 degrees (the input angle
//                      itself); or, with its smallest angle at least Theorem 12's floor for phi,
//                      arcsin(sin(phi / 2) / sqrt 2) (Shewchuk 2001, Sec. 6.3), (2) its shortest edge
//                      joins points on two segments that meet at j at phi, neither being j, and its
//                      third corner lies in the corner triangle that edge cuts off at j (the shells
//                      around the input angle), or, with phi below the -q angle, its ends lie at
//                      distances from j equal within 0.1% (a shell edge, every triangle on which
//                      the Terminator spares there); or (3) its circumcentre lies in the closed diametral
//                      disk of a subsegment at j that bounds a sector of phi under 60 degrees (the
//                      triangles the Terminator may decline, Theorem 12's proof). phi is the sector's
//                      angle (rules 1, 3) or the angle between the two segments (rule 2). Hull edges
//                      (-c, .node inputs) count as segments. A triangle elsewhere, or below the floor,
//                      is not forced by the input angle (docs/manual.md, "Quality accounting");
//                      tests/tools/verify_quality.cpp checks meshes by the same rules;
//   large_input_angle  it misses only --max-angle (or that and a small angle explained as above), and
//                      its angle above the bound lies between two segments at an input vertex or a
//                      crossing;
//                      (at_input_crossings counts those of these two explained at a crossing.)
//   repaired_input     a corner at a vertex deltri made where input segments cross or overlap (not
//                      an input vertex, yet on two or more input segments), the miss not explained
//                      by the angles there;
//   double_precision   its shortest edge is at most kPrecisionUlps ulps of its largest corner
//                      coordinate: no double lies close enough to split it usefully;
//   steiner_limits     -S stopped refinement, or -Y/-YY kept segments whole and the triangle has a
//                      corner on a segment;
//   other              none of these: refinement stopped early (its termination guard) or failed.
#pragma once

#include <cstdint>

#include "geometry/mesh_bounds.h"
#include "mesh/mesh.h"

namespace deltri {

inline constexpr double kPrecisionUlps = 64.0;

struct BoundRequest {
  AngleBound angle;                 // degrees() 0: no angle bound
  SizeBounds size;                  // triangle_bounds: also mesh.area_bound[t] where positive
  LargestAngleBound max_angle;      // --max-angle; not asked(): none
  bool steiner_limited = false;     // -S was reached
  bool segments_kept_whole = false; // -Y or -YY
  unsigned threads = 1;             // from 2, the first pass over the triangles in two halves at once
};

struct BoundMisses {
  std::uint64_t below_angle = 0;  // triangles with an angle below the -q bound
  std::uint64_t above_size = 0;   // triangles above an area or edge-length bound
  std::uint64_t above_max_angle = 0;  // triangles with an angle above the --max-angle bound
  std::uint64_t total = 0;        // triangles missing any (each counted once)
  // total split by cause; the six add up to total.
  std::uint64_t small_input_angle = 0;
  std::uint64_t large_input_angle = 0;  // --max-angle: the angle lies between two input segments
  std::uint64_t repaired_input = 0;
  // Of small_input_angle and large_input_angle: those explained at a crossing of input segments.
  std::uint64_t at_input_crossings = 0;
  std::uint64_t double_precision = 0;
  std::uint64_t steiner_limits = 0;
  std::uint64_t other = 0;
  // What --strict refuses: misses not forced by a small (or, --max-angle, large) input angle, at an
  // input vertex or a crossing.
  std::uint64_t not_forced_by_input() const { return total - small_input_angle - large_input_angle; }
};

BoundMisses count_bound_misses(const Mesh& mesh, const BoundRequest& request);

}  // namespace deltri
