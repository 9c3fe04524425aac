// A certificate, in linear time for ordinary meshes, that the live triangles of a mesh form a
// triangulation in the plane: no two overlap and no corner of one lies on another that it is not
// a corner of. mesh/overlap.h's pair search decides the same in time growing with the number of
// triangles whose boxes meet, which is quadratic on fans and crowded slivers; it runs only when
// this certificate cannot be established (and then also names the offending pair).
//
// What the mesh must already satisfy (-r's assembly and -C's earlier layers check it): every live
// triangle strictly counter-clockwise with corners in range, and link an involution pairing each
// linked edge a->b with an edge b->a. The certificate holds when
//   (B) the boundary edges (those without a twin) form disjoint simple polygons: no vertex has two
//       boundary edges leaving it, two boundary edges that follow each other at a vertex do not
//       double back along one line, and two that do not share an endpoint do not meet at all
//       (exact orient2d; pairs found by box, geometry/box_pairs.h);
//   (W) every boundary loop L has the winding number it needs from the others: at L's lowest
//       vertex q (least x, then y) the loops other than L wind sum 0 times around q when L runs
//       counter-clockwise, once when it runs clockwise (exact crossing counts along a ray).
// Proof that (B) and (W) imply a triangulation:
//   1. For a point p on no edge, let N(p) be the number of triangles containing p and W(p) the
//      sum of the boundary loops' winding numbers around p. Then N(p) = W(p): a counter-clockwise
//      triangle winds once around each inner point and not around outer ones, and in the sum of
//      all triangles' windings (sums of the angles their edges subtend at p) the two edges of each
//      twin pair run opposite ways and cancel, leaving the boundary edges, which make the loops.
//   2. By (B) the loops are disjoint Jordan polygons, so W is constant on each component of the
//      plane minus the loops and grows by exactly 1 across a loop from its right to its left. A
//      counter-clockwise loop winds once around the points on its left near it, a clockwise one
//      not at all; so just left of L, W = [L counter-clockwise] + (the others' winding at q) = 1
//      by (W), and just right of L, W = 0. Every component borders some loop, so W is 0 or 1
//      everywhere off the loops, and N(p) <= 1: no two triangles' interiors overlap (an overlap
//      is open and would hold points on no edge).
//   3. A corner v of u on a closed triangle t, v not a corner of t, contradicts 2 or (B). If all
//      of v's edges are twinned, the triangles at v form closed fans, each turning a positive
//      multiple of a full circle, so they cover a disc around v, which overlaps t. Otherwise v has
//      a boundary edge g. If v is inside t, u overlaps t. If v is inside an edge e of t, either u
//      overlaps t or u lies beyond e: a twin of e would overlap u, so e is a boundary edge and g
//      meets e at v, inside e. If v is at a corner w of t (another vertex at the same place), w's
//      fan overlaps u unless w has a boundary edge too, and then g and w's boundary edge meet at
//      v. Boundary edges that meet so either share no endpoint, or share one and double back: (B)
//      excludes both.
// Neither step needs the fans around vertices to wind once (a fan wound twice round a vertex
// makes its boundary loop cross itself) or the mesh to be connected. Refused, and left to the pair
// search: a vertex with two boundary edges leaving it (two fans touching at a vertex, a "bow
// tie", which may still be a triangulation), and meshes where the box pairs of boundary edges or
// the crossing counts exceed a linear budget (many long boundary edges, many loops on one line).
#pragma once

#include "geometry/predicates.h"
#include "mesh/mesh.h"

namespace deltri {

// True when (B) and (W) hold, which proves that no two live triangles overlap or meet other than
// at shared corners; false when they fail or were not established (proving nothing).
bool certify_embedding(const Mesh& mesh, Predicates& pred);

}  // namespace deltri
