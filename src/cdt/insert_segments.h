// The constrained Delaunay stage, part one: makes every input segment a chain of mesh edges.
#pragma once

#include <cstddef>
#include <utility>
#include <vector>

#include "geometry/predicates.h"
#include "mesh/mesh.h"
#include "pslg/pslg.h"

namespace deltri {

// What had to be repaired in the input, for the warning lines, and what came out.
struct SegmentReport {
  std::size_t duplicates_remapped = 0;  // segment endpoints moved from a duplicate to its original
  std::size_t zero_length = 0;          // segments whose two ends are the same vertex (ignored)
  std::size_t repeated = 0;             // segments identical to an earlier one (ignored)
  std::size_t split_at_vertices = 0;    // times a segment passed exactly through a vertex
  std::size_t overlaps_merged = 0;      // segments sharing a collinear piece with an earlier one
  std::size_t crossings = 0;            // crossing points (each became a vertex, or reused one)
  std::size_t invalid_endpoints = 0;    // segments naming a vertex that does not exist (ignored)
  std::size_t unrecovered = 0;          // segments whose endpoint is in no triangle (e.g. all
                                        // input vertices collinear): ignored
  std::size_t snapped = 0;              // vertices within a few ulps of a segment that split it
  std::size_t midpoints = 0;            // -s: midpoints inserted to make segments edges
  std::size_t subsegments = 0;          // size of mesh.subsegments at the end
};

// Inserts `segments` (in input order) into the Delaunay triangulation in `mesh` and makes it the
// constrained Delaunay triangulation. `duplicates` are (duplicate, kept) vertex pairs from the
// Delaunay stage. Each resulting edge carries a Subsegment {a, b, marker, input index}; a piece
// shared by several segments keeps the first one's record, taking a later marker only when its own
// is 0. A repeated segment with a non-zero marker passes it the same way to the earlier one's
// pieces whose marker is 0. Crossing points become VertexKind::Segment vertices; when rounding
// puts one off a segment, the segment becomes the chain through it (as Triangle does).
// With snap_to_segments (the default; --exact-input turns it off), a vertex within kSnapUlps
// (segment_inserter.h) of a segment's interior splits the segment there, as one exactly on it does.
// With split_to_conform (-s), a segment missing from the triangulation is split at its midpoint,
// recursively, until its pieces are edges, instead of flipping edges to make it one.
// With threads >= 2 the segments are looked for among the edges on two threads first; the result
// is the same for any count.
SegmentReport insert_segments(Mesh& mesh, Predicates& pred, const std::vector<Pslg::Segment>& segments,
                              const std::vector<std::pair<VertexId, VertexId>>& duplicates,
                              bool snap_to_segments = true, bool split_to_conform = false, int threads = 1);

}  // namespace deltri
