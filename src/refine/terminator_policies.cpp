// The Terminator's policies: where a new point goes (the circumcentre or off-centre of a bad
// triangle, a subsegment's split point on concentric shells or mirrored across a thin wedge, a
// double near either at the bottom of double precision) and when the termination guard refuses a
// point (termination_guard.h). The core (terminator_core.cpp) asks; these answer with a point or
// a refusal, reading the algorithm's rules from policy_ (algorithm_policy.h).
#include <algorithm>
#include <cmath>
#include <numbers>

#include "geometry/constructions.h"
#include "geometry/encroachment.h"
#include "geometry/lattice.h"
#include "refine/criteria.h"
#include "refine/bottom_scale.h"
#include "refine/concentric_shells.h"
#include "refine/mirrored_split.h"
#include "refine/range_restricted.h"
#include "refine/restore_delaunay.h"
#include "refine/split_permitted.h"
#include "refine/steiner_point.h"
#include "refine/termination_guard.h"
#include "refine/terminator.h"

namespace deltri {

// Fig. 38 l.13 and the guard's first look. A triangle whose shortest edge is already below the
// floor could only make shorter edges. At the bottom of double precision the point is chosen
// among the doubles near c; if none improves t's neighbourhood, c may still ask for subsegment
// splits (l.18-25) but is not inserted (guard_insertion).
std::optional<Outcome> Terminator::choose_point(TriangleId t, const Assessment& a, Candidate& c) {
  const EdgeRef shortest = a.shape.shortest;
  const Point& g = mesh_.point(mesh_.org(shortest));
  if (std::sqrt(a.shape.shortest_length2) < floor_for(a, g)) return Outcome::BelowFloor;
  // Locally optimal points are for the angle bound; a triangle bad only for its size keeps the
  // off-centre (its circumcentre).
  c.point = optimal_points_ && a.skinny ? petal_.choose(mesh_, pred_, shortest, opt_.angle.degrees(), policy_.off_center_factor)
                                        : steiner_point(mesh_, shortest, policy_.off_center_factor);
  // One bad only for an angle above --max-angle: a candidate whose star meets the bounds
  // (obtuse_point.cpp), the circumcentre failing one.
  if (a.too_obtuse && !a.skinny && !a.too_large)
    c.point = petal_.choose_for_obtuse(mesh_, pred_, edge_of(t, longest_side(a.shape.length2)), c.point,
                                       rules_for(t).angle, opt_.max_angle);
  // A triangle flat to rounding (its measured area 0) has no usable circumcentre: the walk
  // towards a NaN point has no exit side.
  if (!std::isfinite(c.point.x) || !std::isfinite(c.point.y)) return Outcome::NoPoint;
  if (!bottom_.reached(a.shape.shortest_length2, g)) return std::nullopt;
  if (only_for_interior_bound(t, a)) return Outcome::InteriorBoundAtBottom;
  // A shortest edge that no double can make a good triangle with stays bad: refuse at once rather
  // than grade the mesh down around it.
  if (a.skinny && !a.too_large && hopeless_edge(g, mesh_.point(mesh_.dest(shortest)), opt_.angle.sin2()))
    return Outcome::Hopeless;
  if (const std::optional<Point> better = bottom_.point(*this, t, c.point, a)) c.point = *better;
  else c.no_better_double = true;
  return std::nullopt;
}

// The guard on a point about to be inserted, whose nearest vertex is `radius` away.
std::optional<Outcome> Terminator::guard_insertion(const Assessment& a, const Candidate& c, double radius) const {
  if (c.no_better_double) return Outcome::NoBetterDouble;
  if (radius < floor_for(a, c.point)) return Outcome::BelowFloor;
  return std::nullopt;
}

// Fig. 39 l.39: the split point of s (split_point). Out of precision (it rounds onto an end, or a
// neighbour is flush with s there, unless it is one that Chew's step deletes; checked again after
// the step) and at the bottom of double precision the doubles near it are tried
// (BottomScale::split); if none will do, s is locked.
std::optional<Outcome> Terminator::plan_split(EdgeRef s, bool owed_to_size, SplitPlan& plan) {
  const Point& pa = mesh_.point(mesh_.org(s));
  const Point& pb = mesh_.point(mesh_.dest(s));
  Point p = split_point(s);
  const auto out_of_precision = [&](const Point& q) {
    // A split point that overflowed (segments spanning most of the double range) is no point.
    return !std::isfinite(q.x) || !std::isfinite(q.y) || q == pa || q == pb ||
           !split_keeps_orientation(s, q, policy_.deletes_before_split);
  };
  // A double chosen near the split point may lie some ulps off s: only a rounded point on s has
  // its radius bounded by split_clear_of.
  bool chosen_near = false;
  if (bottom_.reached(squared_distance(pa, pb), pa) || out_of_precision(p)) {
    p = bottom_.split(*this, s, p, policy_.deletes_before_split);
    chosen_near = true;
    if (out_of_precision(p)) {
      lock(s);
      return Outcome::Locked;
    }
  }
  plan.point = p;
  plan.exactly_on = exactly_on_axis_parallel_line(pa, pb, p);
  plan.floor = owed_to_size ? bottom_.precision_floor(p) : floor_at(p);
  if (chosen_near || split_radius_read() || !split_clear_of(s, p, plan.floor)) {
    plan.radius = split_radius(s, p);
    if (plan.radius.after_chew < plan.floor) return Outcome::BelowFloor;
  }
  const PieceEnds& piece = pieces_.of_subsegment[mesh_.subseg[s]];
  if (!owed_to_size && BottomScale::creeping_split(pa, pb, p, mesh_.point(piece[0]), mesh_.point(piece[1])))
    return Outcome::BelowFloor;
  return std::nullopt;
}

// Fig. 39 l.39's point before the precision checks. The Terminator's: mirrored across a thin
// wedge, else on concentric shells (or the midpoint); Ruppert's and Chew's algorithms split at the
// midpoint (Sec. 3.1, 4.1). With range-restricted splitting (Sec. 7.3) shells come first, as the
// paper orders them, and every other subsegment follows the ladder of legal lengths; mirrored
// points would leave arbitrary lengths, so they are not used.
Point Terminator::split_point(EdgeRef s) {
  const VertexId a = mesh_.org(s), b = mesh_.dest(s);
  const Point& pa = mesh_.point(a);
  const Point& pb = mesh_.point(b);
  const bool shell_a = policy_.shells && apices_.uses_shells(a), shell_b = policy_.shells && apices_.uses_shells(b);
  if (policy_.legal_lengths && !shell_a && !shell_b)
    return range_restricted_split_point(pa, pb, legal_range_top(policy_.rule.min_apex_angle_deg > 90.0));
  Point p;
  if (!policy_.mirrors || !mirrored_split_point(mesh_, s, pieces_.of_subsegment[mesh_.subseg[s]], pieces_, p))
    p = shell_split_point(pa, pb, shell_a, shell_b);
  return p;
}

// After Chew's step (Fig. 39 l.40-43) the split point is checked again: a free vertex flush with
// s that the step did not delete, or one its search could not reach, still counts.
std::optional<Outcome> Terminator::replan_after_deletions(EdgeRef s, SplitPlan& plan) {
  if (!split_keeps_orientation(s, plan.point, false)) {
    plan.point = bottom_.split(*this, s, plan.point, false);
    plan.exactly_on = false;  // the edges at the new vertex are checked
  }
  if (!split_keeps_orientation(s, plan.point, false)) {
    lock(s);
    return Outcome::Locked;
  }
  if (plan.radius.now < plan.floor && split_insertion_radius(mesh_, pred_, s, plan.point, marks_) < plan.floor)
    return Outcome::BelowFloor;
  return std::nullopt;
}

// Fig. 38 l.21: may the rejected point of triangle a (shortest edge d) have s split? The Terminator
// asks SPLITPERMITTED with --decline-cluster-splits. Ruppert and Chew split every encroached
// subsegment, except with Sec. 7.2's second strategy: a triangle that meets -q, bad only for the 30
// degrees, splits s only where the midpoint's insertion radius |s|/2 is at least d, so that no
// vertex has a descendant with a smaller insertion radius for the sake of the stronger bound.
bool Terminator::split_allowed(EdgeRef s, const Assessment& a, double d) const {
  if (a.too_large) return true;
  if (policy_.interior_strategy == 2 && !below_asked_bound(a))
    return 0.25 * squared_distance(mesh_.point(mesh_.org(s)), mesh_.point(mesh_.dest(s))) >= d * d;
  return !policy_.declines_cluster_splits || split_permitted(mesh_, apices_, s, d);
}

// Sec. 6.2's sure-fire rule, for Ruppert's and Chew's algorithms and range-restricted splitting,
// which have no proof of termination where two segments meet at under 60 degrees (Sec. 3.3, 4,
// 7.3): a subsegment s is not split where the new vertex's insertion radius would be smaller than
// that of its most recently inserted ancestor, a refinement split w on a piece that meets s's piece
// at a common end at under 60 degrees. w is an ancestor when it encroaches upon s (Ruppert's
// mutual encroachment, Fig. 24), or an end of the shortest edge of the skinny triangle whose
// rejected circumcentre asked for the split (the figure-eight cycle of Fig. 26, through a free
// vertex; the newer end, or with Chew's algorithm either: sure_fire_ancestors), or, in Chew's
// algorithm, the vertex the split's insertion radius is measured to once the free vertices in s's
// diametral circle are deleted, when it lies in that circle. Chew splits for no encroaching
// vertex, but that one plays its part: it is what makes the radius small (a split across the
// wedge), and Sec. 3.2 makes the encroaching vertex a split's parent. Without it the cycle ran
// through a free vertex inside a narrow strip between the pieces (the circumcentre of the strip's
// end triangle, across no subsegment): a split asked for by its triangles has only that vertex
// and s's own piece at the shortest edge, and Chew filled such strips down to the edge floor at a
// tiny crossing or between two pieces of equal length (docs/refinement.md, "Chew in thin
// wedges"). Two pieces at an angle phi are coupled: each split of one leads to a split of the
// other, until the subsegments are as short as the gap between the pieces, phi times the distance
// to the apex: about ln(R / r) / phi splits (VVingerfly's test.poly, phi = 2e-6: tens of millions,
// until the memory ran out). With the rule no split is the child of a wider one through the angle,
// so the cycle, whose multiplier is below one, cannot repeat. The paper's exceptions stand: input
// vertices, and splits on pieces that do not share an end with s's (a real feature nearby, which
// bounds refinement by lfs), encroach as always. Where every input angle is 60 degrees or more the
// rule never applies, so meshes in the range of the paper's proofs are unchanged.
// docs/refinement.md, "The sure-fire rule".
bool Terminator::refused_by_sure_fire_rule(EdgeRef s, const SplitPlan& plan) const {
  if (!policy_.tracks_split_radii) return false;
  const PieceEnds& piece = pieces_.of_subsegment[mesh_.subseg[s]];
  const double radius = plan.radius.after_chew;
  const auto ancestor = [&](VertexId w) {
    return w < split_radius_.size() && radius < split_radius_[w] && meets_at_small_angle(piece, w);
  };
  for (const VertexId w : sure_fire_parents_)
    if (w != kNone && ancestor(w)) return true;
  const Point& a = mesh_.point(mesh_.org(s));
  const Point& b = mesh_.point(mesh_.dest(s));
  const VertexId n = plan.radius.nearest;
  if (policy_.chew_ancestors && n != kNone && ancestor(n) &&
      strictly_inside_diametral_circle(a, b, mesh_.point(n)) && !parent_is_input_feature(piece))
    return true;
  for (EdgeRef e : {s, mesh_.link[s]})
    if (e != kNone && ancestor(mesh_.apex(e)) && encroaches(pred_, a, b, mesh_.point(mesh_.apex(e)), policy_.rule)) return true;
  return false;
}

// The paper's exception to its rule: the split's parent (here the newer end of the requesting
// triangle's shortest edge) is an input vertex or a split on a piece that shares no end with s's.
// A real feature then bounds refinement by lfs. It matters for the nearest vertex across a wedge,
// which would otherwise refuse the split an input vertex close to s asks for (an input vertex
// 0.001 off a nonincident segment, next to a 4.4-degree wedge, left a triangle of 0.047 degrees
// on issue-142-double-hanging-edge.poly).
bool Terminator::parent_is_input_feature(const PieceEnds& piece) const {
  const VertexId w = sure_fire_parents_[0];
  if (w == kNone) return false;
  if (mesh_.kind[w] == VertexKind::Input) return true;
  const PieceEnds* other = pieces_.piece_of(w);
  if (other == nullptr || shared_end(piece, *other) != kNone) return false;
  const bool same = (piece[0] == (*other)[0] && piece[1] == (*other)[1]) ||
                    (piece[0] == (*other)[1] && piece[1] == (*other)[0]);
  return !same;
}

// The vertices of a skinny triangle's shortest edge that count as ancestors of the splits its
// rejected circumcentre asks for. The paper's parent is the newer end (Sec. 6.2, Fig. 26), and
// Ruppert's algorithm (and range-restricted splitting) look only at it here: their mutual
// encroachment (an apex of s in its circle or lens, whatever its age) already covers the vertices
// across a thin wedge. Chew's algorithm splits a subsegment only for a circumcentre across it
// (Sec. 4.1), never because a vertex encroaches, so the triangle is its only link across the
// wedge, and both ends count: in a strip between two pieces meeting at a small angle the shortest
// edge spans the strip, and when its newer end lies on the same piece as s (which the rule
// exempts) the older one, across the strip, is the split that the cycle of Fig. 26 runs through.
// Looking only at the newer end, Chew on debug2.poly (0.078-degree spikes) at -pq20 split
// segments 1.96 million times down the spikes (docs/refinement.md, "Chew in thin wedges").
// Where every input angle is 60 degrees or more neither end meets s's piece at a small angle, so
// the paper's proven range is untouched.
std::array<VertexId, 2> Terminator::sure_fire_ancestors(EdgeRef shortest) const {
  const VertexId a = mesh_.org(shortest), b = mesh_.dest(shortest);
  if (!policy_.chew_ancestors) return {std::max(a, b), kNone};
  return {std::max(a, b), std::min(a, b)};
}

// Does refinement split w lie on a piece that meets `piece` at a common end at under 60 degrees?
// Beyond rounding: the corners of an equilateral triangle, written in doubles, measure 60 degrees
// give or take 1e-15, and the paper's proofs (and range-restricted splitting's Theorem 13) hold at
// 60 degrees, so cos must exceed 1/2 by a relative 1e-9.
bool Terminator::meets_at_small_angle(const PieceEnds& piece, VertexId w) const {
  const PieceEnds* other = pieces_.piece_of(w);
  if (other == nullptr) return false;
  const VertexId j = shared_end(piece, *other);
  if (j == kNone) return false;
  const Point& o = mesh_.point(j);
  const Point& p = mesh_.point(piece[0] == j ? piece[1] : piece[0]);
  const Point& q = mesh_.point((*other)[0] == j ? (*other)[1] : (*other)[0]);
  const double ux = p.x - o.x, uy = p.y - o.y, vx = q.x - o.x, vy = q.y - o.y;
  const double dot = ux * vx + uy * vy;
  constexpr double kHalfSquared = 0.25 * (1.0 + 2.0 * kSixtySlack);  // (1/2 (1 + slack))^2
  return dot > 0.0 && dot * dot > kHalfSquared * (ux * ux + uy * uy) * (vx * vx + vy * vy);
}

// Sec. 7.2: strategy 1 holds the triangles with no vertex in a segment interior (none of kind
// Segment: input vertices on a segment are its ends) to 30 degrees, strategy 2 every triangle.
const Criteria& Terminator::interior_rules_for(TriangleId t) const {
  if (policy_.interior_strategy == 2) return interior_rules_;
  for (const VertexId v : mesh_.corners(t))
    if (mesh_.kind[v] == VertexKind::Segment) return rules_;
  return interior_rules_;
}

// Sec. 7.2's 30 degrees are not pursued at the bottom of double precision: is t, assessed as a,
// bad only for them? The paper proves them for input angles of 60 degrees or more; in a narrower
// wedge they cannot hold near the apex, and on lattice triangles a few ulps across refinement went
// on to the Steiner cap (water.poly, a 29-degree corner: ruppert --interior-bound=2 -pq20.7 made
// 930,000 Steiner points within 1e-6 of it).
bool Terminator::only_for_interior_bound(TriangleId t, const Assessment& a) const {
  return policy_.interior_strategy != 0 && !a.too_large && &rules_for(t) == &interior_rules_ && !below_asked_bound(a);
}

// a was assessed under interior_rules_ (ratio2_over_bound2 against its sin^2): is it under -q?
bool Terminator::below_asked_bound(const Assessment& a) const {
  return a.skinny && below_other_bound(a.shape, interior_rules_.angle.sin2(), opt_.angle.sin2());
}

// Whether anything reads a split's radius, or the cavity its search leaves, beyond plan_split's
// comparison with the floor: Ruppert's and Chew's sure-fire rule (split_radius_), Chew's step with
// a free vertex to delete (replan_after_deletions), -Y's check of a split (KeptBoundary). Without
// a free vertex nothing has been inserted but segment splits, each followed by flips that restore
// the constrained Delaunay property, and no vertex has been moved (relocation moves free ones).
bool Terminator::split_radius_read() const {
  return policy_.tracks_split_radii || free_vertices_ || kept_.checks_splits();
}

// Whether every vertex that splitting s at p would join is surely at least `floor` from p, seen
// from the triangles on s alone: in a constrained Delaunay triangulation each vertex seen from a
// triangle's inside lies outside its circumcircle, and the split's new edges go to vertices seen
// from p on either side of s (p is on s, or within a rounding of it, which the slack of
// depth_in_circumcircle covers: a few ulps of the coordinates). On a thin strip the search
// for the split's radius, which this spares, was a sixth of every split's instructions.
bool Terminator::split_clear_of(EdgeRef s, const Point& p, double floor) const {
  for (EdgeRef e : {s, mesh_.link[s]}) {
    if (e == kNone) continue;
    const auto [a, b, c] = mesh_.corner_points(triangle_of(e));
    if (!(depth_in_circumcircle(a, b, c, p) >= floor * (1.0 + 0x1p-40))) return false;
  }
  DELTRI_ASSERT(split_radius_at_least(s, p, floor));
  return true;
}

// The check behind split_clear_of in builds with invariant checks; it leaves the predicate
// counters as they were, so -V reports the same counts in every build.
bool Terminator::split_radius_at_least(EdgeRef s, const Point& p, double floor) const {
  const UncountedCalls uncounted(pred_);
  CavityMarks marks;
  return split_insertion_radius(mesh_, pred_, s, p, marks) >= floor;
}

// The length of the shortest edge that splitting s at p would make, now and once Chew's step (with
// lenses) has deleted the free vertices it deletes: a free vertex a rounding error from s's
// midpoint once made a split owed to a size bound look like a new edge of 1e-15.
Terminator::SplitRadius Terminator::split_radius(EdgeRef s, const Point& p) {
  const double now = split_insertion_radius(mesh_, pred_, s, p, marks_);
  if (!policy_.deletes_before_split || marks_.boundary().empty()) return {now, now};
  const Point& pa = mesh_.point(mesh_.org(s));
  const Point& pb = mesh_.point(mesh_.dest(s));
  double nearest2 = HUGE_VAL;
  VertexId nearest = kNone;
  for (EdgeRef e : marks_.boundary()) {  // the cavity's vertices are its boundary's
    const VertexId w = mesh_.org(e);
    const Point& q = mesh_.point(w);
    if (mesh_.kind[w] == VertexKind::Free && strictly_inside_diametral_circle(pa, pb, q) && too_close_to_split(w, p))
      continue;
    const double d2 = squared_distance(q, p);
    if (d2 < nearest2) {
      nearest2 = d2;
      nearest = w;
    }
  }
  return {now, std::sqrt(nearest2), nearest};
}

// split_edge joins p to the apices on both sides of s. p is rounded, so it is rarely exactly on s;
// when an apex lies within rounding distance of s (a vertex flush with a segment, beyond what
// doubles resolve), p can land on the far side of the line through that apex and a clockwise
// triangle would appear. Such a split is refused, like one whose point rounds onto an endpoint.
bool Terminator::split_keeps_orientation(EdgeRef s, const Point& p, bool chew_pending) {
  // p exactly on s (an axis-parallel s, seen by comparisons) and strictly between its ends: each
  // half is a positive fraction of s, so every apex, strictly left of its side, stays strictly
  // left of both halves (a strip's every split; its orientation tests cost 140 instructions).
  if (strictly_inside_axis_parallel(mesh_.point(mesh_.org(s)), mesh_.point(mesh_.dest(s)), p)) return true;
  for (EdgeRef e : {s, mesh_.link[s]}) {
    if (e == kNone) continue;
    const Point& o = mesh_.point(mesh_.org(e));
    const Point& d = mesh_.point(mesh_.dest(e));
    const VertexId apex = mesh_.apex(e);
    const Point& c = mesh_.point(apex);
    if (chew_pending && mesh_.kind[apex] == VertexKind::Free && strictly_inside_diametral_circle(o, d, c)) continue;
    if (pred_.orient2d(o, p, c) <= 0 || pred_.orient2d(p, d, c) <= 0) return false;
  }
  return true;
}

double Terminator::floor_at(const Point& p) const { return std::max(edge_floor_, bottom_.precision_floor(p)); }

// The feature floor is there to stop cascades of quality splits. A triangle over its size bound
// is split whatever the shapes around it: its circumcentre is at least 0.87 sqrt(area) from
// every vertex of its own, the Steiner cap (which counts the triangles the bounds ask for) ends
// size refinement, and only the precision floor applies. (An area-only run of plate.poly at
// -a0.01 had left one triangle of area 0.015 whose shortest edge was below the floor.)
double Terminator::floor_for(const Assessment& a, const Point& p) const {
  return a.too_large ? bottom_.precision_floor(p) : floor_at(p);
}

bool Terminator::budget_left() {
  const std::uint64_t used = report_.interior_steiner + report_.segment_steiner;
  if (memory_probe_slots_ && used >= kProbeAfterSteiner) ask_memory_budget();
  if (used >= steiner_cap_) {
    report_.stopped_by_cap = true;
    return false;
  }
  if (checks_stall_ && used >= next_stall_check_ && !stall_check_passed(used)) return false;
  if (opt_.max_steiner < 0) return true;
  if (used < static_cast<std::uint64_t>(opt_.max_steiner)) return true;
  report_.stopped_by_max_steiner = true;
  return false;
}

// Obtuse triangles next to small input angles and along thin channels can make each other without
// end (debug2.poly at --max-angle=90: about 120,000 bad triangles queued after 0.13, 0.26 and 0.52
// million Steiner points); the work cap, from the input's features, is tens of millions there.
// So such a run stops, loudly, once the bad triangles queued have not fallen by a sixteenth over a
// doubling of its Steiner points. A check with none queued at the one before (the initial
// subsegment splits fill only Q_s) sets the first mark. Converging runs cut their queue by a tenth
// or more per doubling (water-huge.poly: 8,486, 7,705, 6,892 at 2^16, 2^17, 2^18 points).
bool Terminator::stall_check_passed(std::uint64_t used) {
  next_stall_check_ = 2 * used;
  const std::size_t queued = bad_triangles_.size();
  const std::size_t before = queued_at_last_check_;
  queued_at_last_check_ = queued;
  if (before == 0 || before == SIZE_MAX || queued * 16 < before * 15) return true;
  report_.stopped_by_cap = true;
  set_cap(used, CapKind::Stalled);
  return false;
}

// A run that started small asks for the memory budget when it first reaches kProbeAfterSteiner
// points (TerminatorStart::memory_probe_slots), and its cap becomes the one the budget would have
// set from the start (TerminatorStart::of).
void Terminator::ask_memory_budget() {
  const std::uint64_t memory = memory_cap(*memory_probe_slots_, memory_budget_of(opt_));
  memory_probe_slots_.reset();
  if (memory < steiner_cap_) set_cap(memory, CapKind::Memory);
}

void Terminator::set_cap(std::uint64_t cap, CapKind kind) {
  steiner_cap_ = report_.steiner_cap = cap;
  cap_kind_ = report_.cap_kind = kind;
}

// The equal-shell exemption is the Terminator's (Ruppert's and Chew's algorithms split every skinny
// triangle); the fans of lopped corners stay as they are (Sec. 6.1). It spares a triangle bad only
// for --max-angle as it spares a skinny one: a point for it in the corner makes a new obtuse
// triangle one shell further in, or splits the shells, without end (docs/refinement.md,
// "Largest-angle bound"; the quality account forces it by the same rule).
Assessment Terminator::assess_with(TriangleId t, const Criteria& rules, const SideMeasures& m) const {
  Assessment a = assess_triangle(mesh_, t, rules, m);
  if (lopping_.spares(mesh_, t)) a.skinny = a.too_large = false;
  if (a.skinny && policy_.shell_exemption && shell_exempt(a.shape.shortest)) {
    a.split_instead = beyond_corner_subsegment(a.shape.shortest);
    a.skinny = a.split_instead != kNone;
  }
  if (a.too_obtuse && !a.skinny && !a.too_large && policy_.shell_exemption && shell_exempt(a.shape.shortest))
    a.too_obtuse = false;
  return a;
}

// Miller, Pav and Walkington's rule, which Triangle also follows, kept to the junctions it is for: a
// skinny triangle whose shortest edge ab joins split points on two segment pieces that meet at a
// common endpoint j at under 60 degrees, at equal distances from j, is left alone when the angle at
// j is below the angle bound, and, at or above it, when it lies inside the corner triangle jab. jab is isosceles with the input angle at j; splitting a triangle in
// it only cuts both pieces down again one shell further in, forever when the junction angle is
// small. A triangle on the far side of ab is not in that corner, and nothing forces its angle: left
// alone it stayed at 28.6 degrees beside 42-45 degree junctions where Triangle 1.6 meets 30, and
// a thin wedge filled with ladders of such rungs kept slivers of 1.6 degrees. Its Steiner point
// lies outside the corner, and where it encroaches upon the cluster at j, SPLITPERMITTED decides as
// for any other triangle (Fig. 38 l.21). Equal within 0.1%: split points are rounded.
bool Terminator::shell_exempt(EdgeRef shortest) const {
  const VertexId a = mesh_.org(shortest), b = mesh_.dest(shortest);
  if (!may_lie_on_piece(a) || !may_lie_on_piece(b)) return false;
  const PieceEnds* piece_a = pieces_.piece_of(a);
  const PieceEnds* piece_b = pieces_.piece_of(b);
  if (piece_a == nullptr || piece_b == nullptr) return false;
  const VertexId j = shared_end(*piece_a, *piece_b);
  if (j == kNone) return false;
  const Point &pa = mesh_.point(a), &pb = mesh_.point(b), &pj = mesh_.point(j);
  const double da2 = squared_distance(pa, pj);
  const double db2 = squared_distance(pb, pj);
  constexpr double k = 0.999 * 0.999;  // the distances within 0.1%, compared squared
  if (!(da2 > k * db2 && db2 > k * da2)) return false;
  // Under 60 degrees at j: the base of the isosceles triangle is shorter than its legs.
  const double base2 = squared_distance(pa, pb);
  if (!(base2 < std::min(da2, db2))) return false;
  // Below the angle bound at j (sin^2(phi/2) = |ab|^2 / 4|ja|^2) the corner triangle itself is bad
  // and the shells there are cut down without end if the triangles across ab are split too:
  // sparing only the corner sent random interior segments at -q28 from 69,000 triangles to
  // 2,300,000 with 1,595 left bad, and a corpus file past five minutes. There every triangle on
  // the shell edge is spared, as Triangle does.
  const double half = 0.5 * opt_.angle.degrees() * std::numbers::pi / 180.0;
  if (base2 < 4.0 * std::max(da2, db2) * std::sin(half) * std::sin(half)) return true;
  // At or above the bound the corner triangle is good: only a triangle inside it is spared. The
  // apex c (the triangle is abc, counter-clockwise) inside the closed corner triangle jab.
  const VertexId c = mesh_.apex(shortest);
  if (c == j) return true;
  const Point& pc = mesh_.point(c);
  return pred_.orient2d(pa, pb, pj) > 0.0 && pred_.orient2d(pb, pj, pc) >= 0.0 && pred_.orient2d(pj, pa, pc) >= 0.0;
}

// Shells a factor rho apart along the two sides of a corner of angle t make trapezoids whose
// diagonal triangles have an angle below t exactly when rho > 2 cos t (the triangle joining the
// shell points at r on both sides to the one at rho r has atan(sin t / (rho - cos t)) at the far
// point). Powers of two are such a factor at every corner: beyond a 7.08-degree corner the spared
// triangle had 6.98 degrees, below the input's own angle, which nothing forces. Such a triangle
// (its shortest edge a spared rung ab, its smallest angle, at c, below the input angle at j) has
// its subsegment from a or b to c split; that split is mirrored on the other side (mirrored_split),
// and the trapezoids r..1.5r and 1.5r..2r meet t (1.5 <= 2 cos t up to 41 degrees). The new edges
// are at least half the subsegment long, longer than the rung (2 r sin(t/2) < r/2 under 29
// degrees), so nothing is cut down towards j; the guard's floors refuse the split as any other.
// The corner triangle jab and a triangle whose far vertex is free are left as before, and so is
// every triangle at a junction of three or more segments: there the splits went on from wedge to
// wedge of the cluster until the guard stopped them (CGAL's clusters.poly at -pq33: 1,521
// triangles instead of 229, 71 left under the bound, the worst 3.3 degrees).
EdgeRef Terminator::beyond_corner_subsegment(EdgeRef shortest) const {
  const VertexId a = mesh_.org(shortest), b = mesh_.dest(shortest), c = mesh_.apex(shortest);
  const PieceEnds &piece_a = *pieces_.piece_of(a), &piece_b = *pieces_.piece_of(b);
  const VertexId j = shared_end(piece_a, piece_b);
  if (c == j || !apices_.is_two_segment_corner(j)) return kNone;
  const auto angle = [this](VertexId o, VertexId u, VertexId v) {
    const Point &po = mesh_.point(o), &pu = mesh_.point(u), &pv = mesh_.point(v);
    const double ux = pu.x - po.x, uy = pu.y - po.y, vx = pv.x - po.x, vy = pv.y - po.y;
    return std::atan2(std::fabs(ux * vy - uy * vx), ux * vx + uy * vy);
  };
  const auto far_end = [j](const PieceEnds& piece) { return piece[0] == j ? piece[1] : piece[0]; };
  // The input angle from the input's own vertices; a relative 1e-9 for the rounded split points.
  if (!(angle(c, a, b) < angle(j, far_end(piece_a), far_end(piece_b)) * (1.0 - 1e-9))) return kNone;
  for (EdgeRef e : {lnext(shortest), lprev(shortest)})
    if (mesh_.subseg.has(e) && is_splittable(e)) return e;
  return kNone;
}

Outcome Terminator::split_beyond_corner(EdgeRef s) {
  enqueue_subsegment(s);
  return split_encroached_subsegments(true, false) > 0 ? Outcome::Deferred : Outcome::Declined;
}

}  // namespace deltri
