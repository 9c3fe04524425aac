// Refinement at the bottom of double precision (bottom_scale.h): the policy object BottomScale.
#include "refine/bottom_scale.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "geometry/constructions.h"
#include "geometry/lattice.h"
#include "refine/algorithm_policy.h"
#include "refine/criteria.h"
#include "refine/refine.h"
#include "refine/terminator.h"
#include "refine/termination_guard.h"
#include "util/run_both.h"

namespace deltri {
namespace {

// The largest magnitude of a coordinate in a box, 0 for an empty one.
double largest_coordinate(const Box& box) {
  if (box.empty()) return 0.0;
  return std::max(magnitude({box.lo_x, box.lo_y}), magnitude({box.hi_x, box.hi_y}));
}

}  // namespace

BottomScale::BottomScale(const Mesh& mesh, const RefineOptions& opt, const AlgorithmPolicy& policy,
                         double guard_floor, const Box& extent, std::int64_t known_hopeless)
    : good2_(opt.angle.sin2()), keeps_splits_inside_(policy.keeps_splits_inside), rule_(policy.rule) {
  const bool size_bounds = opt.size.any() || opt.size_test;
  possible_ = size_bounds || guard_floor < ulps_at(largest_coordinate(extent), kBottomScaleUlps);
  if (possible_)
    hopeless_edges_ = known_hopeless >= 0 ? static_cast<std::uint64_t>(known_hopeless)
                                          : count_hopeless_edges(mesh, opt.angle.sin2(), opt.threads);
  if (hopeless_edges_ > 0) precision_scale_ = std::ldexp(1.0, kPrecisionOctaves - kCoarsePrecisionOctaves);
}

// How candidate c for bad triangle t scores at the bottom scale (its cavity just probed): the
// smallest angle sines of the new triangles joining c to the cavity's boundary, those up to twice
// t's scale (`near`) and all of them; nullopt if c is unusable. The new triangles whose shortest
// edge is under sqrt(2) times t's must be good, better than t, or no worse than the triangle they
// replace on their edge. Checking only those no longer-edged than t let a bad lattice triangle
// make bad ones a little longer-edged (26.6 degrees from 31, at -q34), which made more: a front
// that crept out through good territory at one scale without end (issue 47, row 47.d4: 12,000
// Steiner points 1,800 ulps out from a tiny crossing under -S12000). Now badness passes on at
// t's scale only to better triangles or in place of no better ones; otherwise the scale grows by
// sqrt(2), and twelve such steps leave the bottom scale (docs/refinement.md, Termination, item 5).
// sqrt(2) rather than 2: robustness1.node's hull edge at -q20 needs such a step
// (test_bottom_scale.cpp).
constexpr double kGrowth2 = 2.0;  // sqrt(2) times t's shortest edge, squared
std::optional<BottomScale::Score> BottomScale::rate(Terminator& term, const Point& c, const KnownCavity& cavity,
                                                    double l2, double t_sine2) const {
  const Mesh& mesh = term.mesh_;
  const double good2 = good2_;
  Score score{HUGE_VAL, HUGE_VAL};
  for (EdgeRef e : cavity.boundary) {
    const Point& p = mesh.point(mesh.org(e));
    const Point& q = mesh.point(mesh.dest(e));
    if (term.pred_.orient2d(p, q, c) <= 0) return std::nullopt;
    const double s2 = smallest_angle_sine2(p, q, c);
    const double shortest2 = std::min({squared_distance(p, q), squared_distance(p, c), squared_distance(q, c)});
    if (shortest2 < kGrowth2 * l2 && below_angle(s2, good2) && !(s2 > t_sine2) && s2 < triangle_sine2(mesh, triangle_of(e)))
      return std::nullopt;
    if (shortest2 <= 4.0 * l2) score.near = std::min(score.near, s2);
    score.all = std::min(score.all, s2);
  }
  return score;
}

std::optional<Point> BottomScale::point(Terminator& term, TriangleId t, const Point& ideal, const Assessment& a) {
  ++term.report_.bottom_scale_searches;
  std::vector<Point>& candidates = scratch_;
  candidates.clear();
  lattice_neighbourhood(ideal, kBottomScaleSteps, candidates);
  const auto splittable = [&term](EdgeRef e) { return term.is_splittable(e); };
  const double l2 = a.shape.shortest_length2;
  const double t_sine2 = triangle_sine2(term.mesh_, t);
  std::optional<Point> best;
  Score best_score{0.0, 0.0};
  for (const Point& c : candidates) {
    const Probe probe = probe_candidate(term.mesh_, term.pred_, t, c, term.policy_.rule, term.marks_, splittable);
    if (probe.status != ProbeStatus::Clear) continue;
    const double r = probe.insertion_radius;
    if (r < term.floor_for(a, c) || r * r < kBottomRadius2 * l2) continue;
    const KnownCavity cavity = term.marks_.marked();
    if (!cavity.contains(t)) continue;  // c would leave t as it is
    const std::optional<Score> score = rate(term, c, cavity, l2, t_sine2);
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
Point BottomScale::split(Terminator& term, EdgeRef s, const Point& ideal, bool chew_pending) {
  std::vector<Point>& candidates = scratch_;
  candidates.clear();
  lattice_neighbourhood(ideal, kBottomScaleSteps, candidates);
  const Mesh& mesh = term.mesh_;
  const Point& pa = mesh.point(mesh.org(s));
  const Point& pb = mesh.point(mesh.dest(s));
  const PieceEnds& piece = term.pieces_.of_subsegment[mesh.subseg[s]];
  const Point& A = mesh.point(piece[0]);
  const Point& B = mesh.point(piece[1]);
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
    if (!term.split_keeps_orientation(s, c, chew_pending) || beyond_boundary(term, s, c)) continue;
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
bool BottomScale::beyond_boundary(Terminator& term, EdgeRef s, const Point& c) const {
  const Mesh& mesh = term.mesh_;
  if (!keeps_splits_inside_ || mesh.link[s] != kNone) return false;
  return term.pred_.orient2d(mesh.point(mesh.org(s)), mesh.point(mesh.dest(s)), c) < 0;
}

// A subsegment s encroached upon by the apex of a triangle on it whose width (the apex's distance
// to s) is below one ulp of their coordinates, s itself longer than the bottom scale: a strip
// between two segments a fraction of an ulp apart (two segments meeting at an angle of 1e-15
// radians, a segment rounded off a collinear chain). No double lies inside such a strip, so no
// triangle there can meet the bound, and the vertices of each side encroach upon the other's
// subsegments: each split made the halves encroached upon again, down to subsegments of two ulps
// along the whole strip, about 1e16 splits, with the feature floor near 1e-35 (the strip's width
// times its angle) and the Steiner cap from its work far above the memory. The split is refused as
// hopeless, as a short edge that no double can give a good triangle is (choose_point), and the
// triangles are counted. Ordinary meshes have no triangle narrower than an ulp, and splits owed to
// a size bound and subsegments at the bottom scale keep their rules (bottom_scale.h).
// Not where an initial edge is hopeless (precision_scale_ above 1): the coarse floor holds there,
// and robustness2.node, whose hull chains have such strips, kept its mesh only without the rule.
// A strip a few ulps wide is as hopeless when it is long: segments meeting at 1e-15 radians with
// their far ends a few ulps apart need pieces as short as the strip is wide all along it (about
// 1e15 splits under -D or -q). So a subsegment over kLongStripUlps long counts a triangle on it
// narrower than kStripUlps as such a strip; shorter ones are meshed as before.
constexpr double kStripUlps = 16.0, kLongStripUlps = 4096.0;
bool BottomScale::in_strip_below_an_ulp(const Mesh& mesh, Predicates& pred, EdgeRef s) const {
  if (precision_scale_ != 1.0) return false;
  const Point& a = mesh.point(mesh.org(s));
  const Point& b = mesh.point(mesh.dest(s));
  const double length2 = squared_distance(a, b);
  if (at_bottom_scale(length2, a)) return false;
  for (EdgeRef e : {s, mesh.link[s]}) {
    if (e == kNone) continue;
    const Point& c = mesh.point(mesh.apex(e));
    const double twice_area = std::fabs((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
    const double ulp = ulps_at(std::max({magnitude(a), magnitude(b), magnitude(c)}), 1.0);
    // width below an ulp, or below kStripUlps along a subsegment over kLongStripUlps long
    const double width_ulps = kStripUlps * static_cast<double>(length2 > kLongStripUlps * kLongStripUlps * ulp * ulp);
    const double limit = std::max(1.0, width_ulps) * ulp;
    if (!(twice_area * twice_area < limit * limit * length2)) continue;  // first: nearly every apex is far
    // A vertex at the bottom scale from an end is a flush neighbour (split()'s case),
    // not the far side of a strip.
    if (at_bottom_scale(squared_distance(a, c), a) || at_bottom_scale(squared_distance(b, c), b)) continue;
    if (encroaches(pred, a, b, c, rule_)) return true;
  }
  return false;
}

// The bottom of the guard's floor for subsegment splits: no split whose half would join two
// neighbouring doubles (its ends at most one ulp apart in each coordinate, a piece that no double
// can split again). The feature floor can be far below an ulp (1.9e-34 for a wedge of 1e-15
// radians between two segments that leave an ulp cluster), and there the bottom-scale splits of
// one segment's chain crept along the wedge one lattice step at a time, each split making the
// next one's triangles bad (issue 47, item 6: -pq20 to -pq22 ran without end). Such a split is
// refused and its triangles are counted. Halves shorter than 2 ulps of the magnitude but a few
// doubles apart are still allowed: robustness1.node at -q20 splits a subsegment of 3 x ulps by
// 6 y ulps (a y ulp is half an x ulp there), and refusing it left a triangle of 11.3 degrees.
namespace {
double lattice_step(double u, double v) {
  const double m = std::max(std::fabs(u), std::fabs(v));
  return std::nextafter(m, HUGE_VAL) - m;
}
// Surely more than lattice_step(u, v) apart, without nextafter: a step is at most 2^-52 of the
// larger magnitude (2^-1074 below the normal range).
bool far_apart(double u, double v) {
  const double m = std::max(std::fabs(u), std::fabs(v)), d = std::fabs(u - v);
  return m < 0x1p1000 && d > m * 0x1p-51 && d > 0x1p-1000;
}
bool neighbouring_doubles(const Point& a, const Point& b) {
  if (far_apart(a.x, b.x) || far_apart(a.y, b.y)) return false;  // every split but the last few ulps
  return std::fabs(a.x - b.x) <= lattice_step(a.x, b.x) && std::fabs(a.y - b.y) <= lattice_step(a.y, b.y);
}
}  // namespace

// Splitting s (pa-pb, on the segment piece A-B) at p would creep: a half joins neighbouring
// doubles and the piece is over kLongStripUlps long, far longer than any feature the split
// resolves (the pieces inside an ulp cluster are a few ulps long and are meshed down to the
// lattice as before).
bool BottomScale::creeping_split(const Point& pa, const Point& pb, const Point& p, const Point& A, const Point& B) {
  const double ulp = ulps_at(std::max(magnitude(A), magnitude(B)), 1.0);
  if (!(squared_distance(A, B) > kLongStripUlps * kLongStripUlps * ulp * ulp)) return false;
  return neighbouring_doubles(pa, p) || neighbouring_doubles(p, pb);
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

}  // namespace deltri
