// Where to split a subsegment inside a thin wedge (our refinement of Fig. 39 l.39). Two segment
// pieces that leave a common endpoint o at a small angle are split independently, and midpoints
// taken on one rarely line up with the split points of the other. A split point on one piece sees
// a subsegment of the other that it does not line up with at nearly 180 degrees, so it encroaches;
// and the skinny triangles across the wedge are exempt only when their two corners are at equal
// distances from o (Terminator::shell_exempt). Unaligned points thus make each other split again,
// down to subsegments as short as the wedge is wide. Splitting at the point that lies as far from
// o as the vertex across the wedge makes a pair at equal distances instead: the triangle they form
// is exempt and neither encroaches on the other's subsegments. The point is taken only within the
// middle third of the subsegment, the interval the concentric shells use, so the pieces stay
// within 1:2 and the new vertex's insertion radius is at least a third of the subsegment.
#pragma once

#include "mesh/mesh.h"
#include "refine/segment_pieces.h"

namespace deltri {

// True, with p set, when an apex c of a triangle beside s lies on another piece that shares an
// endpoint o with s's piece (as a split point on it, or as its other end), and the point of s at
// distance |oc| from o lies in the middle third of s (the one nearest the middle if both apices
// qualify).
bool mirrored_split_point(const Mesh& mesh, EdgeRef s, const PieceEnds& piece_of_s,
                          const SegmentPieces& pieces, Point& p);

}  // namespace deltri
