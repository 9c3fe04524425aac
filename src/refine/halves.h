// Refining a large mesh as two halves at once, then the seam between them.
//
// Delaunay refinement is local: a Steiner point changes only the triangles whose circumcircles
// contain it. So a mesh cut in two along a chain of its edges, the seam, can be refined on both
// sides at once, each side by its own Terminator on its own arrays on its own thread, as long as
// neither touches the seam: both treat its edges as subsegments they may neither split nor cross
// (kSeamEdge), as -Y treats the boundary. When both are done the halves are joined along the seam,
// Lawson's flips make the seam edges locally Delaunay again (each half is constrained Delaunay, so
// only they can fail the test), and one more Terminator refines what is still bad: the triangles
// the flips made or that lie on the seam, with their subsegments, and those the halves left bad.
// Everything else already meets the bounds, so its queue starts from those alone.
//
// Every vertex is placed by the Terminator's rules, the guard's floor and Steiner cap are those of
// the whole mesh (computed once, before the cut), and the seam's Terminator is an ordinary one on a
// constrained Delaunay mesh: the result meets the same bounds with the same guarantees as one
// Terminator on the whole mesh, though the triangles differ near the seam. It depends neither on
// the threads' timing nor on their number: each half is refined exactly as it would be alone, on
// a thread of its own with two threads or more, one after the other with one.
//
// Used only where it pays and where the halves cannot disagree (halves_apply): RefineOptions::
// in_halves (the default), a large initial mesh, and none of the options that make refinement depend on more than the
// triangles it changes (-S, -Y, -D, declined cluster splits, angle bounds that can cascade, edges
// no double can give a good triangle).
#pragma once

#include "geometry/predicates.h"
#include "mesh/mesh.h"
#include "refine/refine.h"

namespace deltri {

// Meshes with fewer live triangles are refined whole: the cut, the join and the seam cost about
// as much as a few thousand triangles' refinement.
inline constexpr std::uint32_t kHalvesMinTriangles = 20000;

bool halves_apply(const Mesh& mesh, const RefineOptions& opt);

RefineReport refine_in_halves(Mesh& mesh, Predicates& pred, const RefineOptions& opt);

}  // namespace deltri
