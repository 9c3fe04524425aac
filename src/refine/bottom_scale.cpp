// The Terminator at the bottom of double precision (bottom_scale.h).
#include "refine/bottom_scale.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "geometry/constructions.h"
#include "geometry/lattice.h"
#include "refine/criteria.h"
#include "refine/terminator.h"
#include "refine/termination_guard.h"
#include "util/run_both.h"

namespace deltri {

// How candidate c for bad triangle t scores at the bottom scale (its cavity just probed): the
// smallest angle sines of the new triangles joining c to the cavity's boundary, those up to twice
// t's scale (`near`) and all of them; nullopt if c is unusable. The new triangles no longer-edged
// than t must be good, better than t, or no worse than the triangle they replace on their edge.
std::optional<Terminator::BottomScore> Terminator::bottom_score(const Point& c, const KnownCavity& cavity,
                                                                double l2, double t_sine2) {
  const double good2 = opt_.angle.sin2();
  BottomScore score{HUGE_VAL, HUGE_VAL};
  for (EdgeRef e : cavity.boundary) {
    const Point& p = mesh_.point(mesh_.org(e));
    const Point& q = mesh_.point(mesh_.dest(e));
    if (pred_.orient2d(p, q, c) <= 0) return std::nullopt;
    const double s2 = smallest_angle_sine2(p, q, c);
    const double shortest2 = std::min({squared_distance(p, q), squared_distance(p, c), squared_distance(q, c)});
    if (shortest2 <= l2 && below_angle(s2, good2) && !(s2 > t_sine2) && s2 < triangle_sine2(mesh_, triangle_of(e)))
      return std::nullopt;
    if (shortest2 <= 4.0 * l2) score.near = std::min(score.near, s2);
    score.all = std::min(score.all, s2);
  }
  return score;
}

std::optional<Point> Terminator::bottom_scale_point(TriangleId t, const Point& ideal, const Assessment& a) {
  ++report_.bottom_scale_searches;
  std::vector<Point>& candidates = lattice_scratch_;
  candidates.clear();
  lattice_neighbourhood(ideal, kBottomScaleSteps, candidates);
  const auto splittable = [this](EdgeRef e) { return is_splittable(e); };
  const double l2 = a.shape.shortest_length2;
  const double t_sine2 = triangle_sine2(mesh_, t);
  std::optional<Point> best;
  BottomScore best_score{0.0, 0.0};
  for (const Point& c : candidates) {
    const Probe probe = probe_candidate(mesh_, pred_, t, c, policy_.rule, marks_, splittable);
    if (probe.status != ProbeStatus::Clear) continue;
    const double r = probe.insertion_radius;
    if (r < floor_for(a, c) || r * r < kBottomRadius2 * l2) continue;
    const KnownCavity cavity = marks_.marked();
    if (!cavity.contains(t)) continue;  // c would leave t as it is
    const std::optional<BottomScore> score = bottom_score(c, cavity, l2, t_sine2);
    if (!score) continue;
    if (!best || score->near > best_score.near || (score->near == best_score.near && score->all > best_score.all)) {
      best = c;
      best_score = *score;
    }
  }
  return best;
}

// The double near `ideal` that splits s best at the bottom scale: in the middle half of s, with
// the triangles on both sides still counter-clockwise, not outside s where s bounds the mesh, and
// nearest the line of s's segment piece (the subsegment of the initial mesh s lies on), so that a
// chain of such splits never wanders off its segment; the ideal point itself if none qualifies.
Point Terminator::bottom_scale_split(EdgeRef s, const Point& ideal, bool chew_pending) {
  std::vector<Point>& candidates = lattice_scratch_;
  candidates.clear();
  lattice_neighbourhood(ideal, kBottomScaleSteps, candidates);
  const Point& pa = mesh_.point(mesh_.org(s));
  const Point& pb = mesh_.point(mesh_.dest(s));
  const PieceEnds& piece = pieces_.of_subsegment[mesh_.subseg[s]];
  const Point& A = mesh_.point(piece[0]);
  const Point& B = mesh_.point(piece[1]);
  const double ux = B.x - A.x, uy = B.y - A.y;
  const double ex = pb.x - pa.x, ey = pb.y - pa.y, length2 = ex * ex + ey * ey;
  Point best = ideal;
  double best_off = HUGE_VAL, best_balance = 0.0;
  for (const Point& c : candidates) {
    if (c == pa || c == pb) continue;
    const double along = (c.x - pa.x) * ex + (c.y - pa.y) * ey;  // |s| times the distance from pa along s
    const double balance = std::min(along, length2 - along) / length2;
    if (!(balance >= 0.25)) continue;
    const double off = std::fabs(ux * (c.y - A.y) - uy * (c.x - A.x));  // |AB| times the distance
    if (off > best_off || (off == best_off && balance <= best_balance)) continue;
    if (!split_keeps_orientation(s, c, chew_pending) || beyond_boundary(s, c)) continue;
    best = c;
    best_off = off;
    best_balance = balance;
  }
  return best;
}

// On the boundary the piece's line can run an ulp outside s: a split point there made two
// triangles that reached beyond the mesh, over the triangles of a nearly collinear segment a few
// ulps across (water.poly, ruppert --interior-bound=2 -pq20.7: exit 5, triangles overlap). Ruppert's
// and Chew's algorithms, which ping-pong down to the bottom scale at small input angles, keep such
// points inside; the Terminator keeps the rule its meshes were checked with (the corpus and the
// robustness inputs, whose bottom-scale splits on the convex hull have nothing beyond them).
bool Terminator::beyond_boundary(EdgeRef s, const Point& c) {
  if (!policy_.keeps_splits_inside || mesh_.link[s] != kNone) return false;
  return pred_.orient2d(mesh_.point(mesh_.org(s)), mesh_.point(mesh_.dest(s)), c) < 0;
}

std::uint64_t count_hopeless_edges(const Mesh& mesh, double sin2_theta, int threads) {
  if (!(sin2_theta > 0.0)) return 0;
  const auto count_in = [&](EdgeRef from, EdgeRef to) {
    std::uint64_t count = 0;
    for (EdgeRef e = from; e < to; ++e) {
      if (mesh.corner[e] == kNone) continue;
      const VertexId a = mesh.org(e), b = mesh.dest(e);
      if (a > b && mesh.link[e] != kNone) continue;  // each interior edge once
      const Point& pa = mesh.point(a);
      const Point& pb = mesh.point(b);
      count += at_bottom_scale(squared_distance(pa, pb), pa) && hopeless_edge(pa, pb, sin2_theta);
    }
    return count;
  };
  std::uint64_t count[2] = {0, 0};
  run_halves(threads >= 2 && mesh.triangle_slots() >= TerminatorStart::kParallelStartSlots, EdgeRef{0},
             EdgeRef{static_cast<std::uint32_t>(mesh.corner.size())},
             [&](EdgeRef from, EdgeRef to, int half) { count[half] = count_in(from, to); });
  return count[0] + count[1];
}

void Terminator::find_hopeless_edges() {
  report_.hopeless_edges = count_hopeless_edges(mesh_, opt_.angle.sin2(), opt_.threads);
}

}  // namespace deltri
