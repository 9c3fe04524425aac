// Which segment piece each subsegment and each refinement split lies on. A piece is a chain of
// subsegments between two vertices that are not refinement splits (the subsegments of the initial
// mesh); splits keep the piece of the subsegment they split. Two pieces that share an end meet
// there at an input angle, which the shell exemption (Terminator::shell_exempt) and the mirrored
// splits of thin wedges (mirrored_split.h) both need to know.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "mesh/mesh.h"

namespace deltri {

// The endpoints of a segment piece; kNone twice for vertices that are not refinement splits.
using PieceEnds = std::array<VertexId, 2>;

// The end two different pieces share, or kNone (none, or the same piece).
VertexId shared_end(const PieceEnds& mine, const PieceEnds& other);

// The vertices of `mesh` (by id, 1 for such a vertex) where a segment goes straight on: the end of
// exactly two subsegments that leave it in opposite directions, it lying within
// kStraightChainUlps units in the last place of the line through their far ends, and neither
// subsegment at the bottom of double precision (bottom_scale.h). Such a vertex is where an earlier
// run split a segment (the output of -q, -r of it, -p of its .poly), not a corner: its segment
// pieces continue through it as the earlier run's did. Without that, the pieces met at such a
// vertex at 180 degrees, and splits on two segments crossing at a tiny angle no longer shared the
// crossing as their pieces' end: the thin wedge's triangles, left alone by the first run (equal
// shells, shell_exempt), were refined again in the second down the whole wedge (a crossing at
// 1e-7 degrees: -pq30 ended in 0.01 s, -rpq30 of its output ran past the memory). Only for -r
// (RefineOptions::straight_chains): a first run's pieces stay its subsegments, and its meshes as
// they were (GIS outlines such as water.poly have collinear vertices whose pieces shape the splits).
inline constexpr double kStraightChainUlps = 16.0;
// A first run (-p of a .poly) takes the straight chains that end at a sharp junction, where
// another subsegment leaves the chain's end vertex at under kSharpJunctionDeg: the output .poly of
// a run near a tiny crossing has the crossing as an input vertex and the wedges' sides as chains
// of the earlier splits, and the wedges were refined down their whole length (a crossing at 1e-7
// degrees: -pq30 of such a .poly ran past the memory). Chains elsewhere stay pieces of their own.
inline constexpr double kSharpJunctionDeg = 1.0;
std::vector<char> straight_chain_vertices(const Mesh& mesh);

struct SegmentPieces {
  SegmentPieces() = default;
  // Every subsegment of `mesh` an initial piece; with straight_chains, every straight chain of
  // subsegments one piece (straight_chain_vertices), its inner vertices splits of it.
  // sharp_junctions_only: only the chains that end at a sharp junction (kSharpJunctionDeg).
  explicit SegmentPieces(const Mesh& mesh, bool straight_chains = false, bool sharp_junctions_only = false);

  // v split a subsegment of `piece`; mesh's vertex and subsegment records now include the split.
  void record_split(const Mesh& mesh, VertexId v, const PieceEnds& piece);
  // Room for `records` more subsegment records and splits without reallocating.
  void reserve(std::size_t records) {
    of_subsegment.reserve(of_subsegment.size() + records);
    splits.reserve(splits.size() + records);
  }
  // The end o of `mine` such that c lies on another piece from o: c splits such a piece, or c is
  // the far end of an initial one; kNone if there is none.
  VertexId end_shared_with(const PieceEnds& mine, VertexId c) const;

  static std::uint64_t piece_key(VertexId a, VertexId b);
  bool is_initial_piece(VertexId a, VertexId b) const;

  // The piece of refinement split v, or null for a vertex that is not one.
  const PieceEnds* piece_of(VertexId v) const;

  std::vector<PieceEnds> of_subsegment;  // by subsegment record
  // The refinement splits and their pieces, by increasing vertex id (splits are recorded as they
  // are made, and new vertices take increasing ids): 12 bytes per split rather than 8 per vertex.
  struct Split {
    VertexId vertex;
    PieceEnds piece;
  };
  std::vector<Split> splits;
  // piece_key of every initial subsegment, sorted; never changed once made, so the Terminators of
  // two halves (refine/refine_in_parts.h) share one.
  std::shared_ptr<const std::vector<std::uint64_t>> initial;
  void set_initial(std::vector<std::uint64_t> keys);  // sorts them
};

}  // namespace deltri
