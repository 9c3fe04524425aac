#include "improve/smooth.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "geometry/compass.h"
#include "geometry/constructions.h"
#include "mesh/star.h"
#include "refine/criteria.h"

namespace deltri {
namespace {

// Angles are measured in doubles (atan2 of a cross and a dot product, a few ulps off); a move must
// raise the star's smallest angle by more than this, far beyond that rounding, so that "not lower"
// holds for the exact angles too (the same for the sum of a star's smallest angles). The -q test keeps the same distance from the bound.
constexpr double kAngleSlackDeg = 1e-9;

// The ODT point may lie far off; shorter steps towards it are tried when it is refused.
constexpr double kSteps[] = {1.0, 0.5, 0.25};

// The compass search's step budget (its directions: geometry/compass.h).
constexpr int kSearchSteps = 6;

double angle_at(const Point& a, const Point& b, const Point& c) {
  const double ux = b.x - a.x, uy = b.y - a.y, vx = c.x - a.x, vy = c.y - a.y;
  return std::atan2(std::fabs(ux * vy - uy * vx), ux * vx + uy * vy) * (180.0 / std::numbers::pi);
}



// atan(t) for t in [0, 1] to about 1e-5 radians (a minimax polynomial): the compass search only
// ranks its candidates with it; what is kept is judged by atan2.
double atan_unit(double t) {
  const double t2 = t * t;
  return t * (0.9998660 + t2 * (-0.3302995 + t2 * (0.1801410 + t2 * (-0.0851330 + t2 * 0.0208351))));
}

// The angle at a, in degrees, to about 1e-3 degrees.
double rough_angle_at(const Point& a, const Point& b, const Point& c) {
  const double ux = b.x - a.x, uy = b.y - a.y, vx = c.x - a.x, vy = c.y - a.y;
  const double cross = std::fabs(ux * vy - uy * vx), dot = ux * vx + uy * vy, run = std::fabs(dot);
  const double r = run >= cross ? atan_unit(cross / run) : 0.5 * std::numbers::pi - atan_unit(run / cross);
  return (dot < 0.0 ? std::numbers::pi - r : r) * (180.0 / std::numbers::pi);
}

enum class Measure { Exact, Rough };

// The smallest angle is the one opposite the shortest edge (law of sines): one angle, not three.
// Where two edges are within rounding of equal, so are their angles.
template <Measure measure = Measure::Exact>
double smallest_angle(const Point& a, const Point& b, const Point& c) {
  const auto at = measure == Measure::Exact ? angle_at : rough_angle_at;
  const double ab = squared_distance(a, b), bc = squared_distance(b, c), ca = squared_distance(c, a);
  if (ab <= bc && ab <= ca) return at(c, a, b);
  return bc <= ca ? at(a, b, c) : at(b, c, a);
}

double area_of(const Point& a, const Point& b, const Point& c) {
  return 0.5 * std::fabs((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
}

// A star's smallest angle, and the sum over its triangles of each one's smallest angle (the star's
// share of the mesh's mean). A move must raise both, each by more than the rounding of its measure:
// then neither the mesh's smallest angle nor its mean smallest angle can fall.
struct StarQuality {
  double least = 180.0;
  double sum = 0.0;
  bool better_than(const StarQuality& o) const { return least > o.least + kAngleSlackDeg && sum > o.sum + kAngleSlackDeg; }
};

class Smoother {
 public:
  Smoother(Mesh& m, Predicates& pred, const SmoothOptions& opt) : m_(m), pred_(pred), opt_(opt) {}

  // One vertex: true when it moved.
  bool improve(VertexId v, EdgeRef first) {
    if (!gather_star(m_, first, star_) || !changed_since_last_look(v)) return false;
    const Point old = m_.points[v];
    if (!meets_bounds(old)) return false;
    const StarQuality before = quality(old);
    const Point target = odt_point(old);
    if (std::isfinite(target.x) && std::isfinite(target.y))
      for (const double step : kSteps) {
        const Point p{old.x + step * (target.x - old.x), old.y + step * (target.y - old.y)};
        if (p == old) break;
        if (acceptable(p, before)) {
          move(v, p);
          return true;
        }
      }
    const Point p = raise_smallest_angle(old, before);
    if (p == old) return false;
    move(v, p);
    return true;
  }

 private:
  std::size_t size() const { return star_.out.size(); }
  const Point& ring(std::size_t i) const { return m_.points[star_.ring[i]]; }

  // A vertex whose star has not moved since it was last looked at would be refused again: the
  // pass is deterministic. Every accepted move is numbered; each vertex keeps the number of the
  // last move at its last look, and the number of its own last move.
  bool changed_since_last_look(VertexId v) {
    if (looked_at_.empty()) {
      looked_at_.assign(m_.vertex_count(), kNever);
      moved_at_.assign(m_.vertex_count(), 0);
    }
    const std::uint64_t last = looked_at_[v];
    looked_at_[v] = moves_;
    if (last == kNever || moved_at_[v] > last) return true;
    for (std::size_t i = 0; i < size(); ++i)
      if (moved_at_[star_.ring[i]] > last) return true;
    return false;
  }

  void move(VertexId v, const Point& p) {
    m_.points[v] = p;
    moved_at_[v] = ++moves_;
  }

  // The area-weighted mean of the star's circumcentres (Chen and Xu's ODT update for a uniform density).
  Point odt_point(const Point& p) const {
    double sx = 0.0, sy = 0.0, total = 0.0;
    for (std::size_t i = 0; i < size(); ++i) {
      const double a = area_of(p, ring(i), ring(i + 1));
      const Point c = circumcenter(p, ring(i), ring(i + 1));
      sx += a * c.x;
      sy += a * c.y;
      total += a;
    }
    return {sx / total, sy / total};
  }

  // The star's smallest angle and the sum of its triangles' smallest angles, with v at p.
  template <Measure measure = Measure::Exact>
  StarQuality quality(const Point& p) const {
    StarQuality q;
    for (std::size_t i = 0; i < size(); ++i) {
      const double a = smallest_angle<measure>(p, ring(i), ring(i + 1));
      q.least = std::min(q.least, a);
      q.sum += a;
    }
    return q;
  }

  bool triangle_meets_bounds(TriangleId t, const Point& a, const Point& b, const Point& c) const {
    // Kept kAngleSlackDeg clear of -q, so that the exact angle meets it too.
    if (below_angle_bound(smallest_angle(a, b, c) - kAngleSlackDeg, opt_.angle)) return false;
    const double area = area_of(a, b, c);
    if (opt_.size.max_area > 0.0 && area > opt_.size.max_area) return false;
    if (opt_.size.triangle_bounds && m_.area_bound.size() == m_.triangle_slots() && m_.area_bound[t] > 0.0 &&
        area > m_.area_bound[t])
      return false;
    if (opt_.size.max_edge_length > 0.0 &&
        std::max({std::hypot(b.x - a.x, b.y - a.y), std::hypot(c.x - b.x, c.y - b.y), std::hypot(a.x - c.x, a.y - c.y)}) >
            opt_.size.max_edge_length)
      return false;
    if (corner_above(a, b, c, opt_.max_angle) >= 0) return false;
    return opt_.size_test == nullptr || !(*opt_.size_test)(a, b, c, area);
  }

  // Every triangle of the star, with v at p, meets every bound asked for.
  bool meets_bounds(const Point& p) const {
    for (std::size_t i = 0; i < size(); ++i)
      if (!triangle_meets_bounds(triangle_of(star_.out[i]), p, ring(i), ring(i + 1))) return false;
    return true;
  }

  // With v at p: every star triangle counter-clockwise, and every edge of the star locally Delaunay
  // (spokes against the next ring vertex, ring edges against the apex across them).
  bool valid_and_delaunay(const Point& p) {
    for (std::size_t i = 0; i < size(); ++i)
      if (!(pred_.orient2d(p, ring(i), ring(i + 1)) > 0.0)) return false;
    for (std::size_t i = 0; i < size(); ++i) {
      const Point& next = ring((i + 2) % size());
      if (pred_.incircle(p, ring(i), ring(i + 1), next) > 0.0) return false;
      const EdgeRef across = m_.link[lnext(star_.out[i])];
      if (across == kNone) continue;
      if (!opt_.conforming && m_.has_subsegments() && m_.subseg.has(across)) continue;
      if (pred_.incircle(p, ring(i), ring(i + 1), m_.points[m_.apex(across)]) > 0.0) return false;
    }
    return true;
  }

  bool acceptable(const Point& p, const StarQuality& before) {
    return quality(p).better_than(before) && valid_and_delaunay(p) && meets_bounds(p);
  }

  // Where the ODT point lowers the star's smallest angle: a compass search on that angle (the
  // max-min angle objective of optimisation-based smoothing), eight directions at a step that
  // starts at a tenth of the shortest spoke and halves when no direction gains. The directions are
  // ranked by rough angles; the one picked must pass every check with atan2's, so each step taken
  // is a move that could be kept on its own, and the search can stop anywhere.
  Point raise_smallest_angle(const Point& old, const StarQuality& before) {
    double h = 0.1 * shortest_spoke(old);
    Point at = old;
    StarQuality best = before;
    for (int k = 0; k < kSearchSteps && h > 0.0; ++k) {
      Point pick = at;
      const StarQuality here = quality<Measure::Rough>(at);
      StarQuality gain = here;
      for (const auto& d : kCompassDirections) {
        const Point p{at.x + h * d[0], at.y + h * d[1]};
        const StarQuality q = quality<Measure::Rough>(p);
        if (q.better_than(here) && q.least > gain.least) {
          gain = q;
          pick = p;
        }
      }
      if (pick != at && acceptable(pick, best)) {
        at = pick;
        best = quality(pick);
      } else {
        h *= 0.5;
      }
    }
    return at;
  }

  double shortest_spoke(const Point& p) const {
    double least = INFINITY;
    for (std::size_t i = 0; i < size(); ++i) least = std::min(least, std::hypot(ring(i).x - p.x, ring(i).y - p.y));
    return least;
  }

  Mesh& m_;
  Predicates& pred_;
  const SmoothOptions& opt_;
  Star star_;
  static constexpr std::uint64_t kNever = ~std::uint64_t{0};
  std::vector<std::uint64_t> looked_at_, moved_at_;
  std::uint64_t moves_ = 0;
};

// An edge leaving each free vertex (kNone for the others), in vertex id order.
std::vector<EdgeRef> free_vertex_edges(const Mesh& m) {
  std::vector<EdgeRef> edge(m.vertex_count(), kNone);
  for (EdgeRef e{0}; e < m.corner.size(); ++e) {
    const VertexId v = m.corner[e];
    if (v != kNone && m.kind[v] == VertexKind::Free && edge[v] == kNone) edge[v] = e;
  }
  return edge;
}

}  // namespace

SmoothReport smooth_mesh(Mesh& mesh, Predicates& pred, const SmoothOptions& opt) {
  SmoothReport report;
  const std::vector<EdgeRef> edge = free_vertex_edges(mesh);
  Smoother smoother(mesh, pred, opt);
  for (int round = 0; round < opt.rounds; ++round) {
    std::uint64_t moved = 0;
    for (VertexId v{0}; v < mesh.vertex_count(); ++v) {
      if (edge[v] == kNone) continue;
      ++report.tried;
      moved += smoother.improve(v, edge[v]);
    }
    ++report.rounds;
    report.moved += moved;
    if (moved == 0) break;
  }
  return report;
}

}  // namespace deltri
