// The Steiner point of a triangle that is bad only for an angle above --max-angle (an obtuse one at
// 90), after Erten and Ungor ("Computing acute and non-obtuse triangulations", CCCG 2007): among
// candidate points near its long edge, one whose new star meets both angle bounds. The
// circumcentre alone does not converge at 90 degrees: the circumcentre of a nearly right triangle
// lies next to the midpoint of its long edge, and the triangles it makes with the far side of
// that edge are nearly right again (docs/refinement.md, "Largest-angle bound").
#include <cmath>

#include "geometry/constructions.h"

#include "refine/criteria.h"
#include "refine/steiner_point.h"

namespace deltri {
namespace {

// The neighbourhood searched: this many long-edge lengths around its midpoint.
constexpr double kObtuseReach = 1.5;
// Heights of the candidates on the long edge's bisector, in long-edge lengths: beyond the edge
// (the side away from the obtuse corner) and before it.
constexpr double kBeyond[] = {0.05, 0.15, 0.3, 0.45};
constexpr double kBefore[] = {0.05, 0.15};

}  // namespace

Point PetalSearch::choose_for_obtuse(const Mesh& mesh, Predicates& pred, EdgeRef longest, const Point& fallback,
                                     const AngleBound& angle, const LargestAngleBound& max_angle) {
  const Point& p = mesh.point(mesh.org(longest));
  const Point& q = mesh.point(mesh.dest(longest));
  const Point& r = mesh.point(mesh.apex(longest));
  if (!std::isfinite(fallback.x) || !std::isfinite(fallback.y)) return fallback;
  gather(mesh, triangle_of(longest), midpoint(p, q), kObtuseReach * std::sqrt(squared_distance(p, q)));
  mark_walls(mesh);
  propose_obtuse(p, q, fallback);
  Point best = fallback;
  double best_clearance = -1.0;
  for (const Point& x : candidates_) {
    if (!std::isfinite(x.x) || !std::isfinite(x.y) || !(pred.incircle(p, q, r, x) > 0.0)) continue;
    const double clearance = clearance2(x, vertices_);
    if (!(clearance > best_clearance)) continue;  // the cheap test first
    if (star_margin(x, angle, max_angle) >= 0.0) best = x, best_clearance = clearance;
  }
  return best;
}

// The circumcentre first, points on the long edge's bisector, the Voronoi vertices around (the
// gathered triangles' circumcentres) and the midpoints of the Voronoi edges between them.
void PetalSearch::propose_obtuse(const Point& p, const Point& q, const Point& fallback) {
  candidates_.assign(1, fallback);
  const Point m = midpoint(p, q);
  const double nx = -(q.y - p.y), ny = q.x - p.x;  // the left normal of p -> q, pq long: towards the apex
  for (const double h : kBeyond) candidates_.push_back({m.x - h * nx, m.y - h * ny});
  for (const double h : kBefore) candidates_.push_back({m.x + h * nx, m.y + h * ny});
  for (const Point& c : centres_) candidates_.push_back(c);
  for (std::size_t i = 0; i < triangles_.size(); ++i)
    for (unsigned side = 0; side < 3; ++side) {
      const int j = neighbours_[i][side];
      if (j > static_cast<int>(i)) candidates_.push_back(midpoint(centres_[i], centres_[static_cast<std::size_t>(j)]));
    }
}

// How well the triangles x would make with the boundary of its cavity meet the angle bounds
// (angle_margin's least; NaN outside the gathered triangles). The cavity grows from x's
// container across sides that are not subsegments to triangles whose circumcircles hold x; a
// subsegment x encroaches upon (sees at 90 degrees or more) would be split instead, so counts
// as a miss.
double PetalSearch::star_margin(const Point& x, const AngleBound& angle, const LargestAngleBound& max_angle) {
  const int start = container_of(x);
  if (start < 0) return NAN;
  in_cavity_.assign(triangles_.size(), 0);
  in_cavity_[static_cast<std::size_t>(start)] = 1;
  stack_.assign(1, start);
  double margin = 1.0;
  while (!stack_.empty()) {
    const auto i = static_cast<std::size_t>(stack_.back());
    stack_.pop_back();
    for (unsigned side = 0; side < 3; ++side) {
      const int j = neighbours_[i][side];
      if (j >= 0 && in_cavity_[static_cast<std::size_t>(j)]) continue;
      if (j >= 0 && squared_distance(x, centres_[static_cast<std::size_t>(j)]) < radii2_[static_cast<std::size_t>(j)]) {
        in_cavity_[static_cast<std::size_t>(j)] = 1;
        stack_.push_back(j);
        continue;
      }
      const Point& a = corners_[i][side];
      const Point& b = corners_[i][(side + 1) % 3];
      if (walls_[i][side] && (a.x - x.x) * (b.x - x.x) + (a.y - x.y) * (b.y - x.y) <= 0.0) return -1.0;
      margin = std::min(margin, angle_margin(a, b, x, angle, max_angle));
    }
  }
  return margin;
}

// The first gathered triangle (closed) holding x: in the domain, on pq's side of the subsegments
// around (in_gathered).
int PetalSearch::container_of(const Point& x) const {
  for (std::size_t i = 0; i < corners_.size(); ++i)
    if (holds(corners_[i], x)) return static_cast<int>(i);
  return -1;
}

void PetalSearch::mark_walls(const Mesh& mesh) {
  walls_.assign(triangles_.size(), {false, false, false});
  if (!mesh.has_subsegments()) return;
  for (std::size_t i = 0; i < triangles_.size(); ++i)
    for (unsigned side = 0; side < 3; ++side) walls_[i][side] = mesh.subseg.has(edge_of(triangles_[i], side));
}

}  // namespace deltri
