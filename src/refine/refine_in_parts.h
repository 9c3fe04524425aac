// Refining a large mesh in 2^d parts apart, then the seams between them.
//
// Delaunay refinement is local: a Steiner point changes only the triangles whose circumcircles
// contain it. So a mesh cut in two along a chain of its edges, the seam, can be refined on both
// sides apart, each side by its own Terminator on its own arrays, as long as neither touches the
// seam: both treat its edges as subsegments they may neither split nor cross (kSeamEdge), as -Y
// treats the boundary. Each side may itself be cut in two the same way, d levels deep. Once both
// sides of a cut are done they are joined along its seam (mesh/parts.h), Lawson's flips make the
// seam edges locally Delaunay again (each side is constrained Delaunay, so only they can fail the
// test), and one more Terminator refines what is still bad: the triangles the flips made or that
// lie on the seam, with their subsegments, and those the sides left bad. Everything else already
// meets the bounds, so its queue starts from those alone. The joins go level by level, pairs first.
//
// Every vertex is placed by the Terminator's rules, the guard's floor and Steiner cap are those of
// the whole mesh (computed once, before the cuts; each side gets half its part's cap, each seam
// what its sides left), and each seam's Terminator is an ordinary one on a constrained Delaunay
// mesh: the result meets the same bounds with the same guarantees as one Terminator on the whole
// mesh, though the triangles differ near the seams. It depends neither on the threads' timing nor
// on their number: the cuts follow a rule of the input (part_depth), and each part is refined
// exactly as it would be alone, with its own Predicates, queue and marks, whichever thread runs it
// and whenever; with RefineOptions::threads = N the two sides of a cut run at once while threads
// are left (the threads shared out between them), else one after the other.
//
// Used only where it pays and where the parts cannot disagree (parts_apply): RefineOptions::
// in_parts (the default), a large initial mesh, and none of the options that make refinement depend on more than the
// triangles it changes (-S, -Y, -D, declined cluster splits, angle bounds that can cascade, edges
// no double can give a good triangle).
#pragma once

#include "geometry/predicates.h"
#include "mesh/mesh.h"
#include "refine/refine.h"

namespace deltri {

// The parts' rule, a rule of the input and the switches only (never of the threads): 2^d parts,
// d = 1 + floor(log8(live / 20,000)) for a mesh that starts with at least 20,000 live triangles
// (RefineOptions::part_min_triangles), at most kMaxPartDepth, else 0 (refined whole: the cut, the
// join and the seam cost about as much as a few thousand triangles' refinement). The parts grow
// with the square root of the mesh rather than with it because each part still carries a copy of
// every vertex of the whole (mesh/parts.h): an O(vertices) cost per part (docs/refinement.md).
inline constexpr int kMaxPartDepth = 6;
int part_depth(const Mesh& mesh, const RefineOptions& opt);

bool parts_apply(const Mesh& mesh, const RefineOptions& opt);

RefineReport refine_in_parts(Mesh& mesh, Predicates& pred, const RefineOptions& opt);

}  // namespace deltri
