#include "refine/segment_pieces.h"

#include <algorithm>
#include <stdexcept>
#include <utility>

namespace deltri {

VertexId shared_end(const PieceEnds& mine, const PieceEnds& other) {
  const auto has = [&](VertexId v) { return v == other[0] || v == other[1]; };
  if (has(mine[0]) && has(mine[1])) return kNone;  // the same piece
  if (has(mine[0])) return mine[0];
  if (has(mine[1])) return mine[1];
  return kNone;
}

SegmentPieces::SegmentPieces(const Mesh& mesh) {
  std::vector<std::uint64_t> keys;
  keys.reserve(mesh.subsegments.size());
  for (const Subsegment& sub : mesh.subsegments) {
    of_subsegment.push_back({sub.a, sub.b});
    keys.push_back(piece_key(sub.a, sub.b));
  }
  set_initial(std::move(keys));
}

void SegmentPieces::set_initial(std::vector<std::uint64_t> keys) {
  std::sort(keys.begin(), keys.end());
  initial = std::make_shared<const std::vector<std::uint64_t>>(std::move(keys));
}

void SegmentPieces::record_split(const Mesh& mesh, VertexId v, const PieceEnds& piece) {
  if (!splits.empty() && splits.back().vertex >= v) throw std::logic_error("segment splits recorded out of order");
  splits.push_back({v, piece});
  of_subsegment.resize(mesh.subsegments.size(), piece);  // the new half's record
}

const PieceEnds* SegmentPieces::piece_of(VertexId v) const {
  const auto at = std::lower_bound(splits.begin(), splits.end(), v,
                                   [](const Split& s, VertexId u) { return s.vertex < u; });
  return at != splits.end() && at->vertex == v ? &at->piece : nullptr;
}

VertexId SegmentPieces::end_shared_with(const PieceEnds& mine, VertexId c) const {
  if (const PieceEnds* p = piece_of(c)) return shared_end(mine, *p);
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
  return initial && std::binary_search(initial->begin(), initial->end(), piece_key(a, b));
}

}  // namespace deltri
