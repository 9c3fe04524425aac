// Fortune's sweepline algorithm (S. Fortune, "A sweepline algorithm for Voronoi diagrams",
// Algorithmica 2, 1987), used for -F: the Delaunay triangles are the duals of the Voronoi vertices
// the sweep finds.
//
// A horizontal line sweeps upward over the sites (sorted by y, then x). The beach line, the
// upper envelope of the parabolas of points equidistant from a swept site and the sweep line, is a
// doubly linked list of arcs; a site event splits the arc above the new site, and a circle event,
// where an arc shrinks to nothing, is a Voronoi vertex: the arc's site and its two neighbours form
// a Delaunay triangle. Whether three consecutive arcs converge is decided exactly (orient2d), so
// no triangle is lost; only the order of events and the breakpoints used to find the arc above a
// site are floating point. Each breakpoint traces a Voronoi edge, whose two ends make the two
// triangles sharing its dual edge, so triangles are linked as they are made. The result is checked
// to tile the convex hull, and an exact Lawson pass (lawson_pass.h) flips any edge that inexact
// event order left non-Delaunay, and any diagonal of a cocircular polygon that the tie rule of
// Predicates::incircle_perturbed does not choose: the result is divide and conquer's, ties included.
#pragma once

#include <utility>
#include <vector>

#include "geometry/predicates.h"
#include "mesh/mesh.h"

namespace deltri {

// Replaces the triangles of `mesh` by the Delaunay triangulation of its Input vertices, as
// incremental_delaunay does (duplicates reported the same way). Returns false, leaving no
// triangles, if floating-point rounding broke the sweep (the triangles found do not tile the
// convex hull); the caller then uses another algorithm.
bool sweepline_delaunay(Mesh& mesh, Predicates& pred, std::vector<std::pair<VertexId, VertexId>>& duplicates);

}  // namespace deltri
