#include "refine/mirrored_split.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace deltri {
namespace {

double distance(const Point& a, const Point& b) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  return std::sqrt(dx * dx + dy * dy);
}

// The shared endpoint of two different pieces, or kNone.
VertexId common_end(const PieceEnds& mine, const PieceEnds& other) {
  const auto has = [&](VertexId v) { return v == other[0] || v == other[1]; };
  if (has(mine[0]) && has(mine[1])) return kNone;  // the same piece
  if (has(mine[0])) return mine[0];
  if (has(mine[1])) return mine[1];
  return kNone;
}

// The end o of `mine` such that c lies on another piece from o: c splits such a piece, or c is
// the far end of an initial one.
VertexId end_shared_with(const PieceEnds& mine, VertexId c, const SegmentPieces& pieces) {
  if (c < pieces.of_vertex.size() && pieces.of_vertex[c][0] != kNone) return common_end(mine, pieces.of_vertex[c]);
  if (c == mine[0] || c == mine[1]) return kNone;
  for (VertexId o : mine)
    if (pieces.is_initial_piece(o, c)) return o;
  return kNone;
}

}  // namespace

std::uint64_t SegmentPieces::piece_key(VertexId a, VertexId b) {
  if (a > b) std::swap(a, b);
  return static_cast<std::uint64_t>(a) << 32 | b;
}

bool SegmentPieces::is_initial_piece(VertexId a, VertexId b) const {
  return std::binary_search(initial.begin(), initial.end(), piece_key(a, b));
}

bool mirrored_split_point(const Mesh& mesh, EdgeRef s, const PieceEnds& piece_of_s,
                          const SegmentPieces& pieces, Point& p) {
  const Point& a = mesh.point(mesh.org(s));
  const Point& b = mesh.point(mesh.dest(s));
  const double dx = b.x - a.x, dy = b.y - a.y, length2 = dx * dx + dy * dy;
  double off_middle = HUGE_VAL;
  for (EdgeRef side : {s, mesh.link[s]}) {
    if (side == kNone) continue;
    const VertexId c = mesh.apex(side);
    const VertexId o = end_shared_with(piece_of_s, c, pieces);
    if (o == kNone) continue;
    const Point& po = mesh.point(o);
    const Point& far = mesh.point(o == piece_of_s[0] ? piece_of_s[1] : piece_of_s[0]);
    const double along = distance(po, mesh.point(c)) / distance(po, far);
    const Point q{po.x + along * (far.x - po.x), po.y + along * (far.y - po.y)};
    const double t = ((q.x - a.x) * dx + (q.y - a.y) * dy) / length2;  // q's place on s
    if (!(t >= 1.0 / 3.0 && t <= 2.0 / 3.0) || std::fabs(t - 0.5) >= off_middle) continue;
    off_middle = std::fabs(t - 0.5);
    p = q;
  }
  return off_middle != HUGE_VAL;
}

}  // namespace deltri
