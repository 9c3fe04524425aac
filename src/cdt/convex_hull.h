// -c: the convex hull of the vertices is part of the domain, so its edges become segments.
#pragma once

#include <cstddef>

#include "geometry/predicates.h"
#include "mesh/mesh.h"

namespace deltri {

// Gives every boundary edge (link == kNone) without a subsegment a subsegment with marker 1 and
// segment index kNone (it comes from no input segment). Marker 1 is what Triangle gives hull
// edges, and what the boundary rule would give them anyway. Call after insert_segments and before
// carve_holes (with keep_convex_hull). Returns the number of subsegments added.
std::size_t enclose_convex_hull(Mesh& mesh);

// Vertices closer to a hull edge than this many units in the last place of the edge's largest
// coordinate are taken into the edge's chain of subsegments before refinement
// (absorb_near_hull_vertices). A split point of a subsegment is itself rounded by about half an
// ulp, and a checker has to accept chains that far off their line anyway (meshcheck.py takes 16).
inline constexpr double kHullAbsorbUlps = 4.0;

// Before refinement of a domain bounded by its convex hull: an input vertex inside the hull
// within kHullAbsorbUlps of a hull edge (robustness tests whose grid points lie within an ulp of
// the hull, Greenland's coast) forms a triangle with that edge whose angles at the edge's ends are
// 1e-14 degrees, and no split point of the edge can be placed between them in doubles (it rounds
// onto the vertex's side). Such a triangle is removed, so that the vertex joins the hull chain:
// the hull edge from a to b becomes the subsegments a-v and v-b (marker 1, segment kNone). The
// domain loses a sliver at most kHullAbsorbUlps ulps thick. Distances are measured to the line
// through the hull's strictly convex vertices at the ends of the edge's collinear run, so a chain
// of absorbed vertices never wanders further from the hull than the tolerance. Only edges
// carrying hull subsegments (segment index kNone) are looked at. Returns the vertices absorbed.
std::size_t absorb_near_hull_vertices(Mesh& mesh, Predicates& pred);

}  // namespace deltri
