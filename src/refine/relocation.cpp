#include "refine/relocation.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "geometry/constructions.h"

namespace deltri {
namespace {

constexpr double kSlackDeg = 1e-9;
constexpr double kDiagonal = 0.70710678118654752;
constexpr double kDirections[8][2] = {{1, 0}, {kDiagonal, kDiagonal}, {0, 1}, {-kDiagonal, kDiagonal},
                                      {-1, 0}, {-kDiagonal, -kDiagonal}, {0, -1}, {kDiagonal, -kDiagonal}};
constexpr int kSearchSteps = 8;

double angle_at(const Point& a, const Point& b, const Point& c) {
  const double ux = b.x - a.x, uy = b.y - a.y, vx = c.x - a.x, vy = c.y - a.y;
  return std::atan2(std::fabs(ux * vy - uy * vx), ux * vx + uy * vy) * (180.0 / std::numbers::pi);
}

// The smallest angle is the one opposite the shortest edge: one atan2, not three (the search
// measures every star triangle at every step).
double smallest_angle(const Point& a, const Point& b, const Point& c) {
  const double ab = squared_distance(a, b), bc = squared_distance(b, c), ca = squared_distance(c, a);
  if (ab <= bc && ab <= ca) return angle_at(c, a, b);
  return bc <= ca ? angle_at(a, b, c) : angle_at(b, c, a);
}

}  // namespace

bool Relocator::gather(const Mesh& m, EdgeRef first) {
  out_.clear();
  ring_.clear();
  EdgeRef e = first;
  do {
    if (m.has_subsegments() && m.subseg.has(e)) return false;
    out_.push_back(e);
    ring_.push_back(m.dest(e));
    e = m.onext(e);
    if (e == kNone) return false;
  } while (e != first);
  ring_.push_back(ring_.front());
  return out_.size() >= 3;
}

double Relocator::least_angle(const Mesh& m, const Point& p) const {
  double least = 180.0;
  for (std::size_t i = 0; i < out_.size(); ++i)
    least = std::min(least, smallest_angle(p, m.points[ring_[i]], m.points[ring_[i + 1]]));
  return least;
}

bool Relocator::acceptable(const Mesh& m, Predicates& pred, const EncroachRule& rule, const Point& p,
                           double before) const {
  if (!(least_angle(m, p) > before + kSlackDeg)) return false;
  const std::size_t n = out_.size();
  for (std::size_t i = 0; i < n; ++i)
    if (!(pred.orient2d(p, m.points[ring_[i]], m.points[ring_[i + 1]]) > 0.0)) return false;
  for (std::size_t i = 0; i < n; ++i) {
    const Point& a = m.points[ring_[i]];
    const Point& b = m.points[ring_[i + 1]];
    if (pred.incircle(p, a, b, m.points[ring_[(i + 2) % n]]) > 0.0) return false;
    const EdgeRef side = lnext(out_[i]);
    if (m.has_subsegments() && m.subseg.has(side)) {
      if (encroaches(pred, a, b, p, rule)) return false;
      continue;
    }
    const EdgeRef across = m.link[side];
    if (across != kNone && pred.incircle(p, a, b, m.points[m.apex(across)]) > 0.0) return false;
  }
  return true;
}

bool Relocator::relocate(Mesh& m, Predicates& pred, const EncroachRule& rule, EdgeRef first) {
  if (!gather(m, first)) return false;
  const VertexId v = m.org(first);
  const Point old = m.points[v];
  double least = INFINITY;
  for (VertexId w : ring_) least = std::min(least, std::hypot(m.points[w].x - old.x, m.points[w].y - old.y));
  double h = 0.1 * least;
  Point at = old;
  double best = least_angle(m, old);
  for (int k = 0; k < kSearchSteps && h > 0.0; ++k) {
    Point pick = at;
    double gain = best;
    for (const auto& d : kDirections) {
      const Point p{at.x + h * d[0], at.y + h * d[1]};
      const double q = least_angle(m, p);
      if (q > gain + kSlackDeg) gain = q, pick = p;
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
