#include "refine/mirrored_split.h"

#include <cmath>

#include "geometry/constructions.h"

namespace deltri {

bool mirrored_split_point(const Mesh& mesh, EdgeRef s, const PieceEnds& piece_of_s,
                          const SegmentPieces& pieces, Point& p) {
  const Point& a = mesh.point(mesh.org(s));
  const Point& b = mesh.point(mesh.dest(s));
  const double dx = b.x - a.x, dy = b.y - a.y, length2 = squared_distance(a, b);
  double off_middle = HUGE_VAL;
  for (EdgeRef side : {s, mesh.link[s]}) {
    if (side == kNone) continue;
    const VertexId c = mesh.apex(side);
    const VertexId o = pieces.end_shared_with(piece_of_s, c);
    if (o == kNone) continue;
    const Point& po = mesh.point(o);
    const Point& far = mesh.point(o == piece_of_s[0] ? piece_of_s[1] : piece_of_s[0]);
    const double along = std::sqrt(squared_distance(po, mesh.point(c))) / std::sqrt(squared_distance(po, far));
    const Point q{po.x + along * (far.x - po.x), po.y + along * (far.y - po.y)};
    const double t = ((q.x - a.x) * dx + (q.y - a.y) * dy) / length2;  // q's place on s
    if (!(t >= 1.0 / 3.0 && t <= 2.0 / 3.0) || std::fabs(t - 0.5) >= off_middle) continue;
    off_middle = std::fabs(t - 0.5);
    p = q;
  }
  return off_middle != HUGE_VAL;
}

}  // namespace deltri
