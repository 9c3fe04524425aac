#include "refine/relocation.h"

#include <algorithm>
#include <cmath>

#include "geometry/compass.h"
#include "geometry/constructions.h"
#include "refine/criteria.h"

namespace deltri {
namespace {

// Stars are ranked by sin^2 of their smallest angle (smallest_angle_sine2, no atan2: the search
// measures every star triangle at every step, and atan2 dominated its cost). A smallest angle
// is at most 60 degrees, where sin^2 rises with the angle, so the ranking is the angles'; an
// inverted triangle measures 0 and is never picked. The slack is about 1e-9 degrees near 40.
constexpr double kSlack = 1.7e-11;
// Six steps: eight searched longer for no gain (the ten ceiling inputs at -q40, each met, made
// 13,178 triangles with eight and 13,022 with six; docs/refinement.md).
constexpr int kSearchSteps = 6;

// smallest_angle_sine2(p, b, c) with |bc|^2 given (the star's rim does not move), the same
// arithmetic, so the same value to the bit.
inline double rim_triangle_sine2(const Point& p, const Point& b, const Point& c, double bc) {
  const double abx = b.x - p.x, aby = b.y - p.y, acx = c.x - p.x, acy = c.y - p.y;
  const double twice_area = abx * acy - aby * acx;
  if (!(twice_area > 0.0)) return 0.0;
  const double ab = abx * abx + aby * aby, ca = acx * acx + acy * acy;
  return twice_area * twice_area / std::max({ab * bc, bc * ca, ca * ab});
}

}  // namespace

// The rim's points and squared lengths, which every candidate of the search measures against.
void Relocator::read_rim(const Mesh& m) {
  rim_.clear();
  rim2_.clear();
  for (const VertexId w : star_.ring) rim_.push_back(m.points[w]);
  for (std::size_t i = 0; i + 1 < rim_.size(); ++i) {
    const double dx = rim_[i + 1].x - rim_[i].x, dy = rim_[i + 1].y - rim_[i].y;
    rim2_.push_back(dx * dx + dy * dy);
  }
}

// Starts at the triangle that was smallest last time: a nearby candidate's smallest is most often
// the same one, so a candidate no better than floor is dropped after one measure. The order does not
// change the value returned when it is above floor (the minimum), nor the verdict when it is not.
double Relocator::least_angle(const Point& p, double floor) const {
  const std::size_t n = star_.out.size();
  double least = 1.0;
  std::size_t worst = worst_ < n ? worst_ : 0;
  for (std::size_t k = 0, i = worst; k < n && least > floor; ++k, i = i + 1 < n ? i + 1 : 0) {
    const double s = rim_triangle_sine2(p, rim_[i], rim_[i + 1], rim2_[i]);
    if (s < least) least = s, worst = i;
  }
  worst_ = worst;
  return least;
}

// The least angle_margin of the star's triangles with p at the centre, or least_angle without a
// largest-angle goal. Like least_angle it may stop once below floor.
double Relocator::measure(const Point& p, double floor) const {
  if (goal_.max_angle == nullptr) return least_angle(p, floor);
  double least = 1.0;
  for (std::size_t i = 0; i + 1 < rim_.size() && least > floor; ++i)
    least = std::min(least, angle_margin(p, rim_[i], rim_[i + 1], *goal_.angle, *goal_.max_angle));
  return least;
}

bool Relocator::acceptable(const Mesh& m, Predicates& pred, const EncroachRule& rule, const Point& p,
                           double before) const {
  if (!(measure(p, before + kSlack) > before + kSlack)) return false;
  const std::size_t n = star_.out.size();
  for (std::size_t i = 0; i < n; ++i)
    if (!(pred.orient2d(p, m.points[star_.ring[i]], m.points[star_.ring[i + 1]]) > 0.0)) return false;
  for (std::size_t i = 0; i < n; ++i) {
    const Point& a = m.points[star_.ring[i]];
    const Point& b = m.points[star_.ring[i + 1]];
    if (pred.incircle(p, a, b, m.points[star_.ring[(i + 2) % n]]) > 0.0) return false;
    const EdgeRef side = lnext(star_.out[i]);
    if (m.has_subsegments() && m.subseg.has(side)) {
      if (encroaches(pred, a, b, p, rule)) return false;
      continue;
    }
    const EdgeRef across = m.link[side];
    if (across != kNone && pred.incircle(p, a, b, m.points[m.apex(across)]) > 0.0) return false;
  }
  return true;
}

bool Relocator::relocate(Mesh& m, Predicates& pred, const EncroachRule& rule, EdgeRef first, StarGoal goal) {
  if (!gather_star(m, first, star_)) return false;
  goal_ = goal;
  read_rim(m);
  const VertexId v = m.org(first);
  const Point old = m.points[v];
  double least = INFINITY;
  for (VertexId w : star_.ring) least = std::min(least, std::hypot(m.points[w].x - old.x, m.points[w].y - old.y));
  double h = 0.1 * least;
  Point at = old;
  double best = measure(old, -INFINITY);
  for (int k = 0; k < kSearchSteps && h > 0.0; ++k) {
    Point pick = at;
    double gain = best;
    for (const auto& d : kCompassDirections) {
      const Point p{at.x + h * d[0], at.y + h * d[1]};
      const double q = measure(p, gain + kSlack);
      if (q > gain + kSlack) gain = q, pick = p;
    }
    if (pick != at && acceptable(m, pred, rule, pick, best)) {
      at = pick;
      best = gain;
    } else {
      h *= 0.5;
    }
  }
  if (at == old) return false;
  m.points[v] = at;
  return true;
}

}  // namespace deltri
