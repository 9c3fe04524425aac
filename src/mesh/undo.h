// Taking back a vertex insertion, for refinement that tries a vertex and changes its mind.
//
// insert_vertex(mesh, pred, v, hint, split, &flipped) returning {Inserted, edge} leaves all that is
// needed: `edge` lies in the slot that was split (the flips never move v out of it) and `flipped`
// lists the flips in order. undo_insertion unflips them in reverse, then merges the split.
//
// Contract: every change made to the mesh after that insertion has been undone first (insertions
// are undone last-in, first-out). Then every slot that existed before the insertion gets back its
// exact corners, links and subsegments, side for side; the slots the split added are freed; a
// subsegment split by the insertion gets its old endpoint back and the record added for the other
// half is removed if it is still the last one. The vertex itself stays in mesh.points with its
// kind; the caller decides whether to mark it Dead or pop it.
#pragma once

#include <vector>

#include "mesh/mesh.h"

namespace deltri {

void undo_insertion(Mesh& mesh, VertexId v, EdgeRef inserted, const std::vector<EdgeRef>& flipped);

}  // namespace deltri
