#include "refine/steiner_point.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "geometry/constructions.h"
#include "geometry/lattice.h"
#include "refine/criteria.h"

namespace deltri {
namespace {

// The triangles whose circumcircles may meet the petal are a few dozen in a graded mesh. The cap
// bounds the work where the mesh is much finer than pq (next to a short feature), where the
// off-centre is the candidate that matters anyway.
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

// The functions of the bound's angles a petal needs: the same for every search of a run, so they
// are computed when the bound changes only.
const PetalSearch::Trig& PetalSearch::trig_for(double theta_deg) {
  if (trig_.theta_deg == theta_deg) return trig_;
  const double phi = radians(theta_deg + kPetalMarginDeg), theta = radians(theta_deg);
  const double s_min = std::sin(radians(theta_deg + 0.5 * kPetalMarginDeg));
  trig_ = {theta_deg,      std::tan(0.5 * phi),       std::tan(phi),       std::sin(phi), std::cos(phi),
           std::tan(theta), std::sin(theta),          std::cos(theta),     std::sin(0.5 * theta), s_min * s_min};
  return trig_;
}

// pq counter-clockwise with r, so the petal is on the left of p -> q.
PetalSearch::Petal PetalSearch::petal_of(const Point& p, const Point& q, const Point& r, const Trig& trig) {
  Petal petal{p, q, r, {}, {}, 0.0, {}, {}, 0.0, {}, 0.0};
  const double lx = q.x - p.x, ly = q.y - p.y, l = std::sqrt(lx * lx + ly * ly);
  const double ux = lx / l, uy = ly / l, nx = -uy, ny = ux;  // along pq, and its left normal
  const Point mid = midpoint(p, q);
  petal.top = along(mid, nx, ny, 0.5 * l / trig.tan_half_phi);
  petal.arc_centre = along(mid, nx, ny, 0.5 * l / trig.tan_phi);
  petal.arc_radius = 0.5 * l / trig.sin_phi;
  // The rays at angle phi to pq, long enough to cross the arc: a chord of it is at most its diameter.
  const double ray = 2.5 * petal.arc_radius, c = trig.cos_phi, s = trig.sin_phi;
  petal.ray_p = along(p, ux * c - uy * s, uy * c + ux * s, ray);
  petal.ray_q = along(q, -ux * c - uy * s, -uy * c + ux * s, ray);
  petal.holder = along(mid, nx, ny, 0.5 * l / trig.tan_theta);
  petal.holder_radius = 0.5 * l / trig.sin_theta;
  petal.sin2_min = trig.sin2_min;
  return petal;
}

Point PetalSearch::choose(const Mesh& mesh, Predicates& pred, EdgeRef shortest, double theta_deg,
                          double off_center_factor) {
  const Point& p = mesh.point(mesh.org(shortest));
  const Point& q = mesh.point(mesh.dest(shortest));
  const Point& r = mesh.point(mesh.apex(shortest));
  const Point fallback = off_center(p, q, r, off_center_factor);
  const Trig& trig = trig_for(theta_deg);
  const Petal petal = petal_of(p, q, r, trig);
  if (!std::isfinite(fallback.x) || !std::isfinite(fallback.y) || !std::isfinite(petal.holder_radius)) return fallback;
  const Box box = gather_near(mesh, triangle_of(shortest), petal, fallback, trig);
  in_cavity_.assign(triangles_.size(), 0);
  candidates_.assign(1, petal.top);
  propose_corners(petal);
  // A circumcentre is inside its own circle, so only a near one can be admissible.
  for (const int i : near_) candidates_.push_back(centres_[i]);
  propose_voronoi(petal, box);
  note_reachable_vertices(petal, trig);
  Point best = fallback;
  bool best_good = star_meets(fallback, petal.sin2_min, box.holds(fallback));
  double best_clearance = clearance2(fallback, vertices_);
  for (const Point& x : candidates_) {
    if (!box.holds(x)) continue;  // outside pqr's circumcircle for certain: not admissible
    if (best_good) {
      // Behind a good point only a farther good one can win: the distance is the cheap test.
      const double clearance = clearance2(x, reachable_);
      if (!(clearance > best_clearance)) continue;
      if (admissible(pred, petal, x) && judge(x, petal.sin2_min) == Verdict::Good) best = x, best_clearance = clearance;
      continue;
    }
    if (!admissible(pred, petal, x)) continue;
    const Verdict verdict = judge(x, petal.sin2_min);
    if (verdict == Verdict::Outside) continue;
    const double clearance = clearance2(x, reachable_);
    if (verdict == Verdict::Good || clearance > best_clearance)
      best = x, best_good = verdict == Verdict::Good, best_clearance = clearance;
  }
  return best;
}

// The gathered vertices an admissible candidate x can have nearest (reachable_): x sees pq at
// theta or more, so it lies in the holder disk and the nearer of p and q is within
// |pq| / (2 sin(theta / 2)) of it (the petal's top is the farthest); a vertex nearer to x than
// that is within the same of the disk. The others cannot change
// an admissible candidate's clearance2, and the rest of the candidates are refused anyway.
void PetalSearch::note_reachable_vertices(const Petal& petal, const Trig& trig) {
  const double half = 0.5 * std::sqrt(squared_distance(petal.p, petal.q)) / trig.sin_half_theta;
  const double reach = (petal.holder_radius + half) * (1.0 + 1e-6);
  reachable_.clear();
  for (const Point& v : vertices_)
    if (!(squared_distance(v, petal.holder) > reach * reach)) reachable_.push_back(v);
}

// in_gathered and star_meets for a candidate in the admissible box, from one marking of its
// cavity: the triangle holding x is among the marked ones but where rounding says otherwise.
PetalSearch::Verdict PetalSearch::judge(const Point& x, double bound_sin2) {
  mark_cavity(x, near_);
  bool inside = false;
  for (const int i : near_)
    if (in_cavity_[i] && holds(corners_[i], x)) {
      inside = true;
      break;
    }
  if (!inside && !in_gathered(x)) return Verdict::Outside;
  return marked_star_meets(x, bound_sin2, near_) ? Verdict::Good : Verdict::Bad;
}

inline void PetalSearch::mark_cavity(const Point& x, const std::vector<int>& looked_at) {
  const Point* centres = centres_.data();
  const double* radii2 = radii2_.data();
  char* marks = in_cavity_.data();
  for (const int i : looked_at) marks[i] = squared_distance(x, centres[i]) < radii2[i];
}

// Whether every triangle a candidate makes with the boundary of its cavity meets the bound: the
// cavity is the gathered triangles whose circumcircles contain it (the whole cavity, unless it
// reaches past the gathered ones). Only the first miss matters, so the search stops there. For x
// in the admissible box only near_ can hold it (find_near). Between calls in_cavity_ is 0 but
// for the near triangles, whose marks each call writes.
bool PetalSearch::star_meets(const Point& x, double bound_sin2, bool in_box) {
  if (!in_box) {
    all_.resize(triangles_.size());
    for (std::size_t i = 0; i < all_.size(); ++i) all_[i] = static_cast<int>(i);
  }
  const std::vector<int>& looked_at = in_box ? near_ : all_;
  mark_cavity(x, looked_at);
  const bool meets = marked_star_meets(x, bound_sin2, looked_at);
  if (!in_box)
    for (const int i : looked_at) in_cavity_[i] = 0;
  return meets;
}

bool PetalSearch::marked_star_meets(const Point& x, double bound_sin2, const std::vector<int>& looked_at) const {
  for (const int i : looked_at) {
    if (!in_cavity_[i]) continue;
    const auto& corners = corners_[i];
    for (unsigned side = 0; side < 3; ++side) {
      const int j = neighbours_[i][side];
      if (j >= 0 && in_cavity_[j]) continue;
      // A NaN measure misses nothing, as the least taken with std::min did before.
      if (smallest_angle_sine2(corners[side], corners[(side + 1) % 3], x) < bound_sin2) return false;
    }
  }
  return true;
}

// Whether a circumcircle (centre o, squared radius r2) may hold an admissible point or the
// fallback: it meets both pqr's circumcircle and the holder disk (admissible_box), or holds the
// fallback, each widened by a millionth of its size and place (far past rounding). When not, such
// a point is outside the circle in floating point too. A NaN counts as near. Disks rather than
// their boxes: a third fewer triangles gathered (docs/benchmarks.md).
inline bool PetalSearch::Reach::near(const Point& o, double r2) const {
  const double radius = std::sqrt(r2);
  const double own = radius + 1e-6 * (radius + std::fabs(o.x) + std::fabs(o.y));
  const auto apart = [&](const Point& c, double widened) {
    const double reach = own + widened;
    return squared_distance(o, c) > reach * reach;
  };
  const bool out = apart(circle, circle_radius) || apart(holder, holder_radius) || inside_p(o, own) < 0.0 ||
                   inside_q(o, own) < 0.0;
  return !(out && apart(fallback, 0.0));
}

// Whether segment ab is on the far side of the line at p or of the line at q, where an admissible
// point is not: then its crossings with the arc and the rays are not computed (propose_voronoi).
inline bool PetalSearch::Reach::misses(const Point& a, const Point& b) const {
  return (inside_p(a) < 0.0 && inside_p(b) < 0.0) || (inside_q(a) < 0.0 && inside_q(b) < 0.0);
}

// The disks of admissible_box, widened alike, and the lines from p and q at theta to pq (an
// admissible point makes angles of theta or more at p and q: it is on the petal's side of both).
PetalSearch::Reach PetalSearch::reach_of(const Petal& petal, const Point& fallback, const Trig& trig) const {
  const auto widened = [](const Point& c, double radius) {
    return radius * (1.0 + 1e-3) + 1e-9 * (std::fabs(c.x) + std::fabs(c.y));
  };
  const double l = std::sqrt(squared_distance(petal.p, petal.q));
  const double ux = (petal.q.x - petal.p.x) / l, uy = (petal.q.y - petal.p.y) / l;
  const double c = trig.cos_theta, s = trig.sin_theta;
  // The lines' directions are u turned by theta (at p) and -u turned by -theta (at q).
  const Point inward_p{-(uy * c + ux * s), ux * c - uy * s};
  const Point inward_q{ux * s - uy * c, ux * c + uy * s};
  const double rounding = l * 1e-3 + 1e-9 * (std::fabs(petal.p.x) + std::fabs(petal.p.y));
  return {centres_[0], widened(centres_[0], std::sqrt(radii2_[0])), petal.holder,
          widened(petal.holder, petal.holder_radius), fallback, petal.p, petal.q, inward_p, inward_q, rounding};
}

// The triangles that can matter to a candidate in the admissible box (returned): from t (pqr), the
// triangles whose circumcircles may hold an admissible point or the fallback (Reach), reachable from t through such triangles without
// crossing a subsegment (near_), and their other neighbours (the rim, not gone through), whose
// circumcentres end the Voronoi edges that leave the near ones. That is all an admissible x needs:
// in a constrained Delaunay mesh the triangles whose circumcircles hold x are connected and hold
// pqr (x is in its circumcircle), so x's whole cavity is near, its nearest vertex is one of the
// cavity's corners, a circumcentre in the box is a near triangle's, and a Voronoi edge reaches into
// the box only from a near end (a point of it is inside one of its two ends' circumcircles).
PetalSearch::Box PetalSearch::gather_near(const Mesh& mesh, TriangleId t, const Petal& petal, const Point& fallback,
                                          const Trig& trig) {
  start_gathering(mesh, t);
  const Box box = admissible_box(petal, fallback);
  reach_ = reach_of(petal, fallback, trig);
  const Reach& reach = reach_;
  const bool walls = mesh.has_subsegments();
  expanded_.assign(1, 0);
  for (std::size_t k = 0; k < near_.size() && triangles_.size() < kGatherLimit; ++k) {
    const auto next = static_cast<std::size_t>(near_[k]);
    expanded_[next] = 1;
    for (unsigned side = 0; side < 3; ++side) {
      TriangleId u;
      const int known = look_across(mesh, walls, next, side, u);
      if (known < -1) continue;  // a wall: no neighbour
      const unsigned back = side_of(mesh.link[edge_of(triangles_[next], side)]);
      if (known >= 0) {
        neighbours_[next][side] = known;
        neighbours_[static_cast<std::size_t>(known)][back] = static_cast<int>(next);
        continue;
      }
      const auto i = static_cast<int>(triangles_.size());
      neighbours_[next][side] = i;
      remember(u, mesh.corner_points(u));
      neighbours_.back()[back] = static_cast<int>(next);
      describe(static_cast<std::size_t>(i));
      expanded_.push_back(0);
      if (reach.near(centres_.back(), radii2_.back())) near_.push_back(i), expanded_.back() = kLeftNear;
    }
  }
  // The rim's sides towards the near ones are known; the Voronoi edges between two rim triangles
  // miss the admissible points (propose_voronoi), so the rim is not looked around again.
  for (char& e : expanded_) e = e == kLeftNear ? 0 : 1;
  note_vertices_and_rim(mesh, true);
  return box;
}

// t (pqr) gathered alone, and near.
void PetalSearch::start_gathering(const Mesh& mesh, TriangleId t) {
  triangles_.clear();
  corners_.clear();
  neighbours_.clear();
  centres_.clear();
  radii2_.clear();
  slots_.assign(kSlots, kNone);
  remember(t, mesh.corner_points(t));
  describe(0);
  near_.assign(1, 0);
}

inline void PetalSearch::describe(std::size_t i) {
  const auto& [a, b, c] = corners_[i];
  centres_.push_back(circumcenter(a, b, c));
  radii2_.push_back(squared_distance(centres_.back(), a));
}

// The gathered triangles' corners, each once, and the neighbours of those not gone through
// (expanded_ 0: gather_near's near ones left at the limit; gather's last ones).
// With near_only (gather_near), the near triangles' corners only: an admissible point's or the
// fallback's cavity is near, and with it its nearest vertex in sight.
void PetalSearch::note_vertices_and_rim(const Mesh& mesh, bool near_only) {
  vertices_.clear();
  if (++search_ == 0) std::fill(seen_.begin(), seen_.end(), 0), search_ = 1;
  if (seen_.size() < mesh.vertex_count()) seen_.resize(std::max<std::size_t>(mesh.vertex_count(), 2 * seen_.size()), 0);
  const bool walls = mesh.has_subsegments();
  const std::size_t count = near_only ? near_.size() : triangles_.size();
  for (std::size_t n = 0; n < count; ++n) {
    const std::size_t i = near_only ? static_cast<std::size_t>(near_[n]) : n;
    for (unsigned k = 0; k < 3; ++k) note_vertex(mesh, mesh.corner[edge_of(triangles_[i], k)]);
    if (expanded_[i]) continue;
    TriangleId u;
    for (unsigned side = 0; side < 3; ++side) neighbours_[i][side] = std::max(look_across(mesh, walls, i, side, u), -1);
  }
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
void PetalSearch::propose_voronoi(const Petal& petal, const Box& near) {
  Point crossings[2];
  Point at;
  for (std::size_t i = 0; i < triangles_.size(); ++i) {
    for (unsigned side = 0; side < 3; ++side) {
      const int j = neighbours_[i][side];
      if (j <= static_cast<int>(i)) continue;  // each edge once, both ends gathered
      const Point& a = centres_[i];
      const Point& b = centres_[static_cast<std::size_t>(j)];
      if (near.misses(a, b) || reach_.misses(a, b)) continue;
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
// An admissible candidate also makes triangle pqx meet the bound, so its angle at x is at least
// theta: x is in the disk through p and q from which pq subtends theta (Petal::holder), and in the
// box around that disk too. Last, the box takes in the fallback, whose cavity is scored as well.
PetalSearch::Box PetalSearch::admissible_box(const Petal& petal, const Point& fallback) const {
  const auto around = [](const Point& c, double radius) {
    const double reach = radius * (1.0 + 1e-3) + 1e-9 * (std::fabs(c.x) + std::fabs(c.y));
    return Box{c.x - reach, c.x + reach, c.y - reach, c.y + reach};
  };
  const Box circle = around(centres_[0], std::sqrt(radii2_[0]));
  const Box disk = around(petal.holder, petal.holder_radius);
  const Box both{std::max(circle.x_lo, disk.x_lo), std::min(circle.x_hi, disk.x_hi), std::max(circle.y_lo, disk.y_lo),
                 std::min(circle.y_hi, disk.y_hi)};
  return {std::min(both.x_lo, fallback.x), std::max(both.x_hi, fallback.x), std::min(both.y_lo, fallback.y),
          std::max(both.y_hi, fallback.y)};
}

// In the petal (triangle pqx meets the bound, with the margin) and in pqr's circumcircle.
bool PetalSearch::admissible(Predicates& pred, const Petal& petal, const Point& x) const {
  if (!std::isfinite(x.x) || !std::isfinite(x.y)) return false;
  if (!(smallest_angle_sine2(petal.p, petal.q, x) >= petal.sin2_min)) return false;
  return pred.incircle(petal.p, petal.q, petal.r, x) > 0.0;
}

// In one of the gathered triangles (closed): in the domain, on pq's side of the subsegments around.
// The near ones are looked at first; the others only when none of those holds x.
bool PetalSearch::in_gathered(const Point& x) const {
  for (const int i : near_)
    if (holds(corners_[i], x)) return true;
  return container_of(x) >= 0;
}

double PetalSearch::clearance2(const Point& x, const std::vector<Point>& vertices) {
  double nearest = HUGE_VAL;
  for (const Point& v : vertices) nearest = std::min(nearest, squared_distance(x, v));
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

// What lies across side `side` of gathered triangle i: kWall (the hull or a subsegment), or a
// triangle u (set) and its index_of.
inline int PetalSearch::look_across(const Mesh& mesh, bool walls, std::size_t i, unsigned side, TriangleId& u) const {
  const EdgeRef e = edge_of(triangles_[i], side);
  const EdgeRef across = mesh.link[e];
  if (across == kNone || (walls && mesh.subseg.has(e))) return kWall;
  u = triangle_of(across);
  return index_of(u);
}

inline void PetalSearch::remember(TriangleId t, const Mesh::CornerPoints& at) {
  const std::size_t slot = slot_of(t);
  slots_[slot] = t;
  slot_index_[slot] = static_cast<int>(triangles_.size());
  triangles_.push_back(t);
  corners_.push_back({at.a, at.b, at.c});
  neighbours_.push_back({-1, -1, -1});
}

// The triangles reachable from t without crossing a subsegment whose bounding boxes meet the disk
// of radius `reach` around `centre`. Each side looked across gives its neighbour's index at once
// (the other end's status never changes after), so only the sides of the triangles the limit left
// unexplored are looked up again (describe_gathered).
void PetalSearch::gather(const Mesh& mesh, TriangleId t, const Point& centre, double reach) {
  triangles_.clear();
  corners_.clear();
  neighbours_.clear();
  slots_.assign(kSlots, kNone);
  remember(t, mesh.corner_points(t));
  const bool walls = mesh.has_subsegments();
  std::size_t next = 0;
  for (; next < triangles_.size() && triangles_.size() < kGatherLimit; ++next) {
    for (unsigned side = 0; side < 3; ++side) {
      TriangleId u;
      const int known = look_across(mesh, walls, next, side, u);
      if (known != -1) {  // a wall, gathered, or refused already (the test is u's alone)
        neighbours_[next][side] = std::max(known, -1);
        continue;
      }
      const auto at = mesh.corner_points(u);
      const auto [a, b, c] = at;
      const double dx = std::max({std::min({a.x, b.x, c.x}) - centre.x, 0.0, centre.x - std::max({a.x, b.x, c.x})});
      const double dy = std::max({std::min({a.y, b.y, c.y}) - centre.y, 0.0, centre.y - std::max({a.y, b.y, c.y})});
      if (dx * dx + dy * dy <= reach * reach) {
        neighbours_[next][side] = static_cast<int>(triangles_.size());
        remember(u, at);
      } else {
        refuse(u);
      }
    }
  }
  describe_gathered(mesh, next);
}

// Their circumcircles, their corners each once, and the neighbours (across no subsegment) of the
// triangles from `explored` on, whose sides gather did not look across (note_vertices_and_rim).
void PetalSearch::describe_gathered(const Mesh& mesh, std::size_t explored) {
  centres_.clear();
  radii2_.clear();
  for (std::size_t i = 0; i < triangles_.size(); ++i) describe(i);
  expanded_.assign(triangles_.size(), 0);
  std::fill_n(expanded_.begin(), explored, 1);
  note_vertices_and_rim(mesh, false);
}

// Each corner once (clearance2 takes the least distance, so their order does not matter): a stamp
// per vertex of the mesh (seen_, sized by describe_gathered) marks those seen by this search,
// instead of sorting the ids each time.
inline void PetalSearch::note_vertex(const Mesh& mesh, VertexId v) {
  const auto i = static_cast<std::size_t>(static_cast<std::uint32_t>(v));
  if (seen_[i] == search_) return;
  seen_[i] = search_;
  vertices_.push_back(mesh.point(v));
}

}  // namespace deltri
