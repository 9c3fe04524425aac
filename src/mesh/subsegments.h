// The kernel's subsegment edits: attaching records to edges and removing them. Every one keeps
// mesh.h's invariant that an edge and its twin carry the same subsegment, and that a record with
// a == kNone (dead) is carried by no live edge once drop_dead_subsegments has run.
#pragma once

#include <cstddef>

#include "mesh/mesh.h"

namespace deltri {

// Appends record s and attaches it to edge e and its twin. Returns its id.
SubsegmentId constrain(Mesh& mesh, EdgeRef e, const Subsegment& s);

// Detaches the subsegment of e (and its twin) and marks its record dead. Returns the record as it
// was, so the caller can queue its pieces.
Subsegment unconstrain(Mesh& mesh, EdgeRef e);

// Gives every boundary edge (link == kNone) without a subsegment a new subsegment with `marker`
// and segment index kNone (it comes from no input segment), in slot order. Enables the
// subsegment array. Returns the number added.
std::size_t constrain_boundary(Mesh& mesh, int marker);

// Records with a == kNone are dead. Removes them, keeping the others in order, and renumbers the
// ids stored on edges, so consumers never see a dead record.
void drop_dead_subsegments(Mesh& mesh);

// Marks dead every record no live edge carries any more (the triangles on both sides were
// removed), clears the subsegment entries of dead slots, then drops the dead records. Returns the
// number of records that died here.
std::size_t drop_unused_subsegments(Mesh& mesh);

// Removes the triangle (a, b, v) of the boundary edge e = a->b, whose subsegment s must then run
// a -> v -> b: s's record becomes a-v (on the edge a->v, now boundary) and a new record (same
// marker and segment index) is put on v->b. The other two edges of the triangle must have twins.
// Returns the two new boundary edges, a->v and v->b.
struct PeeledEdges {
  EdgeRef av = kNone, vb = kNone;
};
PeeledEdges peel_boundary_triangle(Mesh& mesh, EdgeRef e);

}  // namespace deltri
