// SegmentPieces::piece_of finds a refinement split's piece among the splits recorded by
// increasing vertex id: checked against a scan of the list, on runs of consecutive split ids (a
// strip's refinement, where the entry sits at v minus the first split's id) broken by gaps of
// vertices that are not splits, and for ids before, between and after the splits.
#include <random>

#include "harness/check.h"
#include "refine/segment_pieces.h"

using namespace deltri;

namespace {

const PieceEnds* scanned(const SegmentPieces& pieces, VertexId v) {
  for (const SegmentPieces::Split& s : pieces.splits)
    if (s.vertex == v) return &s.piece;
  return nullptr;
}

}  // namespace

TEST(piece_of_matches_a_scan_over_runs_and_gaps) {
  std::mt19937 rng(45);
  for (int trial = 0; trial < 50; ++trial) {
    SegmentPieces pieces;
    std::uint32_t v = 10 + rng() % 5;
    const int runs = 1 + static_cast<int>(rng() % 6);
    for (int r = 0; r < runs; ++r) {
      const std::uint32_t length = 1 + rng() % 40;
      for (std::uint32_t i = 0; i < length; ++i, ++v)
        pieces.splits.push_back({VertexId{v}, {VertexId{v % 7}, VertexId{1000 + v}}});
      v += trial % 3 == 0 ? 0 : rng() % 9;  // a gap of vertices that are not splits, or none
    }
    for (std::uint32_t u = 0; u < v + 5; ++u) {
      const PieceEnds* found = pieces.piece_of(VertexId{u});
      const PieceEnds* expected = scanned(pieces, VertexId{u});
      CHECK_EQ(found, expected);
    }
  }
  CHECK(SegmentPieces{}.piece_of(VertexId{0}) == nullptr);
}
