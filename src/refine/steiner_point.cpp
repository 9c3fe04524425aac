#include "refine/steiner_point.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "geometry/constructions.h"
#include "geometry/lattice.h"
#include "refine/criteria.h"

namespace deltri {
namespace {

// The neighbourhood searched is a few times pq's length across; in a graded mesh that is a few
// dozen triangles. The cap bounds the work where the mesh is much finer than pq (next to a short
// feature), where the off-centre is the candidate that matters anyway.
constexpr std::size_t kGatherLimit = 96;
// The table holds the gathered triangles and those refused next to them (at most three neighbours
// per gathered one), with room to spare for short probes.
static_assert(PetalSearch::kSlots > 1 + kGatherLimit * 7 / 2);

double radians(double degrees) { return degrees * std::numbers::pi / 180.0; }

Point along(const Point& from, double ux, double uy, double length) {
  return {from.x + ux * length, from.y + uy * length};
}

}  // namespace

Point steiner_point(const Mesh& mesh, EdgeRef shortest, double off_center_factor) {
  return off_center(mesh.point(mesh.org(shortest)), mesh.point(mesh.dest(shortest)), mesh.point(mesh.apex(shortest)),
                    off_center_factor);
}

Point steiner_point_of(const Point& a, const Point& b, const Point& c, double off_center_factor) {
  const Point* p[3] = {&a, &b, &c};
  const double len2[3] = {squared_distance(a, b), squared_distance(b, c), squared_distance(c, a)};
  const unsigned s = shortest_side(len2);
  return off_center(*p[s], *p[(s + 1) % 3], *p[(s + 2) % 3], off_center_factor);
}

// pq counter-clockwise with r, so the petal is on the left of p -> q.
PetalSearch::Petal PetalSearch::petal_of(const Point& p, const Point& q, const Point& r, double theta_deg) {
  Petal petal{p, q, r, {}, {}, 0.0, {}, {}, 0.0, 0.0};
  const double phi = radians(theta_deg + kPetalMarginDeg);
  const double lx = q.x - p.x, ly = q.y - p.y, l = std::sqrt(lx * lx + ly * ly);
  const double ux = lx / l, uy = ly / l, nx = -uy, ny = ux;  // along pq, and its left normal
  const Point mid = midpoint(p, q);
  petal.top = along(mid, nx, ny, 0.5 * l / std::tan(0.5 * phi));
  petal.arc_centre = along(mid, nx, ny, 0.5 * l / std::tan(phi));
  petal.arc_radius = 0.5 * l / std::sin(phi);
  // The rays at angle phi to pq, long enough to cross the arc: a chord of it is at most its diameter.
  const double ray = 2.5 * petal.arc_radius, c = std::cos(phi), s = std::sin(phi);
  petal.ray_p = along(p, ux * c - uy * s, uy * c + ux * s, ray);
  petal.ray_q = along(q, -ux * c - uy * s, -uy * c + ux * s, ray);
  petal.reach = 0.5 * l / std::tan(0.5 * phi) + l / std::sin(phi);
  const double s_min = std::sin(radians(theta_deg + 0.5 * kPetalMarginDeg));
  petal.sin2_min = s_min * s_min;
  return petal;
}

Point PetalSearch::choose(const Mesh& mesh, Predicates& pred, EdgeRef shortest, double theta_deg,
                          double off_center_factor) {
  const Point& p = mesh.point(mesh.org(shortest));
  const Point& q = mesh.point(mesh.dest(shortest));
  const Point& r = mesh.point(mesh.apex(shortest));
  const Point fallback = off_center(p, q, r, off_center_factor);
  const Petal petal = petal_of(p, q, r, theta_deg);
  if (!std::isfinite(fallback.x) || !std::isfinite(fallback.y) || !std::isfinite(petal.reach)) return fallback;
  gather(mesh, triangle_of(shortest), midpoint(p, q), petal.reach);
  candidates_.assign(1, petal.top);
  propose_corners(petal);
  for (const Point& c : centres_) candidates_.push_back(c);
  propose_voronoi(petal);
  Point best = fallback;
  Score best_score = score(fallback, petal.sin2_min);
  for (const Point& x : candidates_) {
    const bool best_good = best_score.shape >= petal.sin2_min;
    // Behind a good point only a farther one can win: the distance is the cheap test.
    if (best_good && !(clearance2(x) > best_score.clearance2)) continue;
    if (!admissible(pred, petal, x) || !in_gathered(x)) continue;
    const Score s = score(x, petal.sin2_min);
    const bool good = s.shape >= petal.sin2_min;
    if ((good && !best_good) || (good == best_good && s.clearance2 > best_score.clearance2))
      best = x, best_score = s;
  }
  return best;
}

// A candidate's new triangles are those it makes with the boundary of its cavity: the gathered
// triangles whose circumcircles contain it (the whole cavity, unless it reaches past the gathered
// ones). Their smallest angle counts up to the bound: beyond it a larger star is worth more.
PetalSearch::Score PetalSearch::score(const Point& x, double bound_sin2) {
  in_cavity_.assign(triangles_.size(), 0);
  for (std::size_t i = 0; i < triangles_.size(); ++i)
    in_cavity_[i] = squared_distance(x, centres_[i]) < radii2_[i];
  double shape = bound_sin2;
  for (std::size_t i = 0; i < triangles_.size(); ++i) {
    if (!in_cavity_[i]) continue;
    for (unsigned side = 0; side < 3; ++side) {
      const int j = neighbours_[i][side];
      if (j >= 0 && in_cavity_[static_cast<std::size_t>(j)]) continue;
      const Point& a = corners_[i][side];
      const Point& b = corners_[i][(side + 1) % 3];
      shape = std::min(shape, smallest_angle_sine2(a, b, x));
    }
  }
  return {shape, clearance2(x)};
}

// The two ends of the arc, where the rays meet it: the petal's corners.
void PetalSearch::propose_corners(const Petal& petal) {
  Point crossings[2];
  for (const Point* far : {&petal.ray_p, &petal.ray_q}) {
    const Point& from = far == &petal.ray_p ? petal.p : petal.q;
    const int n = segment_circle_crossings(from, *far, petal.arc_centre, petal.arc_radius, crossings);
    for (int i = 0; i < n; ++i) candidates_.push_back(crossings[i]);
  }
}

// The crossings of the Voronoi edges between the gathered triangles (their circumcentres, joined
// across edges that carry no subsegment) with the arc and the rays.
void PetalSearch::propose_voronoi(const Petal& petal) {
  Point crossings[2];
  Point at;
  const Box near = admissible_box();
  for (std::size_t i = 0; i < triangles_.size(); ++i) {
    for (unsigned side = 0; side < 3; ++side) {
      const int j = neighbours_[i][side];
      if (j <= static_cast<int>(i)) continue;  // each edge once, both ends gathered
      const Point& a = centres_[i];
      const Point& b = centres_[static_cast<std::size_t>(j)];
      if (near.misses(a, b)) continue;
      const int n = segment_circle_crossings(a, b, petal.arc_centre, petal.arc_radius, crossings);
      for (int k = 0; k < n; ++k) candidates_.push_back(crossings[k]);
      if (segment_crossing(a, b, petal.p, petal.ray_p, at)) candidates_.push_back(at);
      if (segment_crossing(a, b, petal.q, petal.ray_q, at)) candidates_.push_back(at);
    }
  }
}

// A box around pqr's circumcircle (triangles_[0] is pqr), widened far past rounding: an admissible
// candidate is inside that circle (the exact incircle test), and a crossing on a Voronoi edge lies
// in the edge's bounding box, so an edge whose box misses it proposes nothing admissible and its
// crossings need not be computed (most of the gathered edges, which surround the petal).
PetalSearch::Box PetalSearch::admissible_box() const {
  const Point& c = centres_[0];
  const double reach = std::sqrt(radii2_[0]) * (1.0 + 1e-3) + 1e-9 * (std::fabs(c.x) + std::fabs(c.y));
  return {c.x - reach, c.x + reach, c.y - reach, c.y + reach};
}

// Disjoint for certain. An edge with a NaN or infinite end may count as disjoint either way: its
// crossings are not finite, and admissible() refuses them.
bool PetalSearch::Box::misses(const Point& a, const Point& b) const {
  return std::max(a.x, b.x) < x_lo || std::min(a.x, b.x) > x_hi || std::max(a.y, b.y) < y_lo ||
         std::min(a.y, b.y) > y_hi;
}

// In the petal (triangle pqx meets the bound, with the margin) and in pqr's circumcircle.
bool PetalSearch::admissible(Predicates& pred, const Petal& petal, const Point& x) const {
  if (!std::isfinite(x.x) || !std::isfinite(x.y)) return false;
  if (!(smallest_angle_sine2(petal.p, petal.q, x) >= petal.sin2_min)) return false;
  return pred.incircle(petal.p, petal.q, petal.r, x) > 0.0;
}

// In one of the gathered triangles (closed): in the domain, on pq's side of the subsegments around.
bool PetalSearch::in_gathered(const Point& x) const { return container_of(x) >= 0; }

double PetalSearch::clearance2(const Point& x) const {
  double nearest = HUGE_VAL;
  for (const Point& v : vertices_) nearest = std::min(nearest, squared_distance(x, v));
  return nearest;
}

// A small open-addressed table from triangle to its place in triangles_ or kRefused (kSlots is
// well above what a gather can enter, so probes are short and it never fills).
static_assert(PetalSearch::kSlots == std::size_t{1} << (32 - 23));  // slot_of's shift
std::size_t PetalSearch::slot_of(TriangleId t) const {
  std::size_t slot = (static_cast<std::uint32_t>(t) * 2654435761u) >> 23;
  while (slots_[slot] != kNone && slots_[slot] != t) slot = (slot + 1) % kSlots;
  return slot;
}

int PetalSearch::index_of(TriangleId t) const {
  const std::size_t slot = slot_of(t);
  return slots_[slot] == kNone ? -1 : slot_index_[slot];
}

void PetalSearch::refuse(TriangleId t) {
  const std::size_t slot = slot_of(t);
  slots_[slot] = t;
  slot_index_[slot] = kRefused;
}

void PetalSearch::remember(TriangleId t) {
  const std::size_t slot = slot_of(t);
  slots_[slot] = t;
  slot_index_[slot] = static_cast<int>(triangles_.size());
  triangles_.push_back(t);
}

// The triangles reachable from t without crossing a subsegment whose bounding boxes meet the disk
// of radius `reach` around `centre`.
void PetalSearch::gather(const Mesh& mesh, TriangleId t, const Point& centre, double reach) {
  triangles_.clear();
  slots_.assign(kSlots, kNone);
  remember(t);
  for (std::size_t next = 0; next < triangles_.size() && triangles_.size() < kGatherLimit; ++next) {
    for (unsigned side = 0; side < 3; ++side) {
      const EdgeRef e = edge_of(triangles_[next], side);
      const EdgeRef across = mesh.link[e];
      if (across == kNone || (mesh.has_subsegments() && mesh.subseg.has(e))) continue;
      const TriangleId u = triangle_of(across);
      if (index_of(u) != -1) continue;  // gathered, or refused already (the test is u's alone)
      const auto [a, b, c] = mesh.corner_points(u);
      const double dx = std::max({std::min({a.x, b.x, c.x}) - centre.x, 0.0, centre.x - std::max({a.x, b.x, c.x})});
      const double dy = std::max({std::min({a.y, b.y, c.y}) - centre.y, 0.0, centre.y - std::max({a.y, b.y, c.y})});
      if (dx * dx + dy * dy <= reach * reach) remember(u); else refuse(u);
    }
  }
  describe_gathered(mesh);
}

// Their corners, circumcircles and which of them are neighbours (across no subsegment).
void PetalSearch::describe_gathered(const Mesh& mesh) {
  centres_.clear();
  radii2_.clear();
  corners_.clear();
  vertices_.clear();
  if (++search_ == 0) std::fill(seen_.begin(), seen_.end(), 0), search_ = 1;
  neighbours_.assign(triangles_.size(), {-1, -1, -1});
  for (std::size_t i = 0; i < triangles_.size(); ++i) {
    const auto [a, b, c] = mesh.corner_points(triangles_[i]);
    const Point centre = circumcenter(a, b, c);
    centres_.push_back(centre);
    radii2_.push_back(squared_distance(centre, a));
    corners_.push_back({a, b, c});
    for (unsigned k = 0; k < 3; ++k) note_vertex(mesh, mesh.corner[edge_of(triangles_[i], k)]);
    for (unsigned side = 0; side < 3; ++side) {
      const EdgeRef e = edge_of(triangles_[i], side);
      const EdgeRef across = mesh.link[e];
      if (across == kNone || (mesh.has_subsegments() && mesh.subseg.has(e))) continue;
      neighbours_[i][side] = std::max(index_of(triangle_of(across)), -1);
    }
  }
}

// Each corner once (clearance2 takes the least distance, so their order does not matter): a stamp
// per vertex of the mesh marks those seen by this search, instead of sorting the ids each time.
void PetalSearch::note_vertex(const Mesh& mesh, VertexId v) {
  const auto i = static_cast<std::size_t>(static_cast<std::uint32_t>(v));
  if (i >= seen_.size()) seen_.resize(std::max<std::size_t>(i + 1, 2 * seen_.size()), 0);
  if (seen_[i] == search_) return;
  seen_[i] = search_;
  vertices_.push_back(mesh.point(v));
}

}  // namespace deltri
