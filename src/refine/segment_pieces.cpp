#include "refine/segment_pieces.h"

#include <algorithm>
#include <utility>

namespace deltri {

VertexId shared_end(const PieceEnds& mine, const PieceEnds& other) {
  const auto has = [&](VertexId v) { return v == other[0] || v == other[1]; };
  if (has(mine[0]) && has(mine[1])) return kNone;  // the same piece
  if (has(mine[0])) return mine[0];
  if (has(mine[1])) return mine[1];
  return kNone;
}

SegmentPieces::SegmentPieces(const Mesh& mesh) : of_vertex(mesh.vertex_count(), {kNone, kNone}) {
  for (const Subsegment& sub : mesh.subsegments) {
    of_subsegment.push_back({sub.a, sub.b});
    initial.push_back(piece_key(sub.a, sub.b));
  }
  std::sort(initial.begin(), initial.end());
}

void SegmentPieces::record_split(const Mesh& mesh, VertexId v, const PieceEnds& piece) {
  of_vertex.resize(mesh.vertex_count(), {kNone, kNone});
  of_vertex[v] = piece;
  of_subsegment.resize(mesh.subsegments.size(), piece);  // the new half's record
}

VertexId SegmentPieces::end_shared_with(const PieceEnds& mine, VertexId c) const {
  if (c < of_vertex.size() && of_vertex[c][0] != kNone) return shared_end(mine, of_vertex[c]);
  if (c == mine[0] || c == mine[1]) return kNone;
  for (VertexId o : mine)
    if (is_initial_piece(o, c)) return o;
  return kNone;
}

std::uint64_t SegmentPieces::piece_key(VertexId a, VertexId b) {
  if (a > b) std::swap(a, b);
  return static_cast<std::uint64_t>(a) << 32 | b;
}

bool SegmentPieces::is_initial_piece(VertexId a, VertexId b) const {
  return std::binary_search(initial.begin(), initial.end(), piece_key(a, b));
}

}  // namespace deltri
