// Restoring the constrained Delaunay property around a vertex placed by split_edge (Fig. 39
// l.44). A segment split point is rounded, so it is rarely exactly on the subsegment and
// insert_vertex's exact location would not put it there; the split is made by hand and the
// link of the new vertex is then flipped by Lawson's rule, never across a subsegment; and since
// the rounded point is rarely exactly on the subsegment, the edges at the new vertex are checked
// too, unless the caller knows it is on it (exactly_on).
#pragma once

#include <algorithm>

#include "geometry/predicates.h"
#include "mesh/mesh.h"

namespace deltri {

// `out` leaves v. Returns an edge leaving v afterwards. `exactly_on` says v lies exactly on the
// subsegment it split: then Lawson's flips of the link alone restore the property, as after an
// exact insertion, and the edges at v need no check.
EdgeRef restore_delaunay_around(Mesh& mesh, Predicates& pred, VertexId v, EdgeRef out, bool exactly_on);

// Whether p lies exactly on the line through a and b, seen by comparisons alone: a horizontal or
// vertical a-b (orient2d's filter cannot decide a zero; its exact stage costs more than it saves).
inline bool exactly_on_axis_parallel_line(const Point& a, const Point& b, const Point& p) {
  return (a.y == b.y && p.y == a.y) || (a.x == b.x && p.x == a.x);
}

// Whether p lies exactly on the axis-parallel segment a-b, strictly between its ends, by comparisons.
inline bool strictly_inside_axis_parallel(const Point& a, const Point& b, const Point& p) {
  if (a.y == b.y && p.y == a.y) return std::min(a.x, b.x) < p.x && p.x < std::max(a.x, b.x);
  if (a.x == b.x && p.x == a.x) return std::min(a.y, b.y) < p.y && p.y < std::max(a.y, b.y);
  return false;
}

}  // namespace deltri
