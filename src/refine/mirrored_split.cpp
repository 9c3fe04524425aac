#include "refine/mirrored_split.h"

#include <cmath>

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

}  // namespace

bool mirrored_split_point(const Mesh& mesh, EdgeRef s, const PieceEnds& piece_of_s,
                          const std::vector<PieceEnds>& piece_of_vertex, Point& p) {
  const Point& a = mesh.point(mesh.org(s));
  const Point& b = mesh.point(mesh.dest(s));
  const double dx = b.x - a.x, dy = b.y - a.y, length2 = dx * dx + dy * dy;
  double off_middle = HUGE_VAL;
  for (EdgeRef side : {s, mesh.link[s]}) {
    if (side == kNone) continue;
    const VertexId c = mesh.apex(side);
    if (c >= piece_of_vertex.size() || piece_of_vertex[c][0] == kNone) continue;
    const VertexId o = common_end(piece_of_s, piece_of_vertex[c]);
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
