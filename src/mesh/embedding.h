// A certificate, in linear time for ordinary meshes, that the live triangles of a mesh form a
// triangulation in the plane: no two overlap and no corner of one lies on another that it is not
// a corner of. mesh/overlap.h's pair search decides the same in time growing with the number of
// triangles whose boxes meet, which is quadratic on fans and crowded slivers; it runs only when
// this certificate cannot be established (and then also names the offending pair).
//
// What the mesh must already satisfy (-r's assembly and -C's earlier layers check it): every live
// triangle strictly counter-clockwise with corners in range, and link an involution pairing each
// linked edge a->b with an edge b->a. Call the edges without a twin boundary edges; at every vertex
// as many leave as reach it (twins pair the others). The certificate holds when
//   (B) boundary edges meet only at common endpoints: the boundary edges at a vertex (leaving and
//       reaching it) lie in pairwise different directions from it, and two with no endpoint in
//       common do not meet at all (exact orient2d; pairs found by box, geometry/box_pairs.h);
//       where several leave a vertex (a "bow tie": fans touching at it), they alternate with
//       those reaching it in the exact angular order round it;
//   (W) with next(e), for e reaching v, the boundary edge leaving v next clockwise from e (the
//       only one when one leaves v), the edges form loops; for each loop L, at its lowest vertex
//       q (least x, then y), where L's edge e arrives and f = next(e) leaves, W(p) = 1 for the
//       points p just counter-clockwise of f round q. One loop without bow ties needs only to run
//       counter-clockwise at q; otherwise W there is counted exactly: the signed crossings of
//       boundary edges with a ray from q towards +x, then one up for each boundary edge leaving
//       q and one down for each reaching it in the directions passed turning from +x to f.
// Proof that (B) and (W) imply a triangulation:
//   1. For a point p on no edge, let N(p) be the number of triangles containing p and W(p) the
//      sum of the boundary edges' windings round p (the angles they subtend, over 2 pi; the
//      loops' winding numbers). Then N(p) = W(p): a counter-clockwise triangle winds once round
//      each inner point and not round outer ones, and in the sum of all triangles' windings the
//      two edges of each twin pair run opposite ways and cancel, leaving the boundary edges.
//   2. By (B) two boundary edges meet at most at a common endpoint (at one they leave it in
//      different directions, so as segments they meet only there). So W is constant off them
//      near any point of one and grows by exactly 1 across an edge from its right to its left.
//      At a vertex v, an edge e reaching v and next(e) bound a sector round v that lies on the
//      left of both and holds no other boundary edge at v (next is a bijection by the
//      alternation), so W just left of e equals W just left of next(e): it is constant along
//      each loop, 1 by (W), and W is 1 just left of every boundary edge and 0 just right of it.
//      Every component of the plane minus the boundary edges borders one, so W is 0 or 1 off
//      them and N(p) <= 1: no two triangles' interiors overlap (an overlap is open and would
//      hold points on no edge). The count in (W) is W: the ray from q + (s, s d), 0 < d << s,
//      towards +x crosses the edges not at q as the ray from q does with each edge's lower end
//      counted and its upper one not (no edge but those at q passes through q), and none at q;
//      that point lies just counter-clockwise of +x round q, and turning on to f, W rises across
//      each edge leaving q and falls across each reaching it. A single loop without bow ties is
//      a simple polygon, 1 on its left iff it runs counter-clockwise.
//   3. A corner v of u on a closed triangle t, v not a corner of t, contradicts 2 or (B). If all
//      of v's edges are twinned, the triangles at v form closed fans, each turning a positive
//      multiple of a full circle, so they cover a disc around v, which overlaps t. Otherwise v has
//      a boundary edge g. If v is inside t, u overlaps t. If v is inside an edge e of t, either u
//      overlaps t or u lies beyond e: a twin of e would overlap u, so e is a boundary edge and g
//      meets e at v, inside e. If v is at a corner w of t (another vertex at the same place), w's
//      fan overlaps u unless w has a boundary edge too, and then g and w's boundary edge meet at
//      v, a common endpoint of both only under two ids. (B) excludes each.
// Neither step needs the fans around vertices to wind once (a fan wound twice round a vertex
// makes its boundary loop cross itself) or the mesh to be connected, nor the fans at a bow tie to
// be walked: two fans overlapping at it break the alternation, and step 2 does the rest. Refused,
// and left to the pair search: meshes where the box pairs of boundary edges or the crossing
// counts exceed a linear budget (many long boundary edges, many loops on one line).
#pragma once

#include "geometry/predicates.h"
#include "mesh/mesh.h"

namespace deltri {

// True when (B) and (W) hold, which proves that no two live triangles overlap or meet other than
// at shared corners; false when they fail or were not established (proving nothing).
bool certify_embedding(const Mesh& mesh, Predicates& pred);

}  // namespace deltri
