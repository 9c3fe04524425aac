#include "refine/kept_boundary.h"

#include <algorithm>
#include <cmath>

#include "geometry/constructions.h"
#include "geometry/encroachment.h"
#include "refine/algorithm_policy.h"
#include "refine/criteria.h"
#include "refine/steiner_point.h"
#include "refine/terminator.h"

namespace deltri {
namespace {

// sin^2 of the smallest angle of the live triangles, 1 for none.
double smallest_sine2(const Mesh& mesh) {
  double smallest = 1.0;
  for (TriangleId t{0}; t < mesh.triangle_slots(); ++t) {
    if (mesh.is_live(t)) smallest = std::min(smallest, triangle_sine2(mesh, t));
  }
  return smallest;
}

// sin^2 of half the acute angle whose sin^2 is s2: (1 - cos) / 2.
double half_angle_sine2(double s2) { return 0.5 * (1.0 - std::sqrt(std::max(0.0, 1.0 - s2))); }

// Rule (0)'s floor where no subsegment may be split: min(angle bound, the mesh's smallest angle).
// Without a size bound a dip below it is allowed down to half its angle: Triangle 1.6 makes one on
// bicycle_seat.poly -pYYq33 and mends it (docs/refinement.md, "-Y, -YY", "Rule 0's dip").
double kept_floor_sine2(const Mesh& mesh, double bound_sin2, bool size_bounds) {
  const double floor = std::min(bound_sin2, smallest_sine2(mesh));
  return size_bounds ? floor : half_angle_sine2(floor);
}

// Whether -Y/-YY leave every subsegment whole: -YY, or -Y where every segment lies on the
// boundary. Then only insertions change the mesh, and rule (0) of KeptBoundary::refuses keeps
// its smallest angle at the floor (half of it without a size bound); where interior segments are
// split, their splits are not bound by it, and neither is an insertion.
bool keeps_every_subsegment(const Mesh& mesh, int no_steiner_on_segments) {
  if (no_steiner_on_segments != 1) return no_steiner_on_segments >= 2;
  if (!mesh.has_subsegments()) return true;
  for (EdgeRef e{0}; e < mesh.corner.size(); ++e)
    if (mesh.corner[e] != kNone && mesh.subseg.has(e) && mesh.link[e] != kNone) return false;
  return true;
}

}  // namespace

bool keeps_boundary(const RefineOptions& opt) { return opt.no_steiner_on_segments > 0; }

KeptBoundary::KeptBoundary(const RefineOptions& opt)
    : level_(opt.no_steiner_on_segments),
      checks_splits_(opt.no_steiner_on_segments != 0 && !opt.conforming_delaunay),
      bound_sin2_(AngleBound(std::max(opt.angle.degrees(), kLeastLensDeg)).sin2()) {}

void KeptBoundary::start(const Mesh& mesh, bool size_bounds) {
  if (keeps_every_subsegment(mesh, level_)) floor_sin2_ = kept_floor_sine2(mesh, bound_sin2_, size_bounds);
}

// -Y/-YY: may c, whose probe was just made, be inserted? c replaces the triangles of its cavity
// (CavityMarks) by those it makes with the cavity's boundary. It is refused when
//  (0) where no subsegment may be split (-YY, or -Y with segments on the boundary only), it would
//      make a triangle below the floor, min(angle bound, smallest angle of the mesh the Terminator
//      started from), and worse than every triangle it replaces. Then no insertion lowers the
//      smallest angle of the mesh below the floor, and as nothing else changes the mesh, the
//      result has no angle below it (docs/refinement.md, "-Y, -YY": the initial constrained
//      Delaunay triangulation shows the fixed boundary allows that much). Without a size bound
//      the floor is half that angle: a dip that a later point mends is allowed, as Triangle 1.6
//      makes one (bicycle_seat.poly -pYYq33: 34.35 degrees instead of the floor, 32.12); the whole
//      floor is measured there, not proved. Elsewhere floor_sin2_ is 0.
//  (1) it would make a triangle below the bound, worse than every triangle it replaces, that no
//      later point can mend (would_strand): its own Steiner point lies behind a kept subsegment or
//      in the lens of one. Delaunay refinement makes worse triangles on its way everywhere and
//      splits them in their turn; next to a kept boundary that turn may never come (guitar.poly
//      -pYYq33 kept a 7.1 degree triangle made for a 24.5 degree one).
// The triangle on a kept subsegment s changes only when a new point lands in its circumcircle,
// that is when s is on the boundary of the point's cavity, and the point then becomes its apex.
// So c is also refused when, for a kept s on the cavity's boundary,
//  (2) c encroaches upon s (lies in its lens): the rule of Fig. 38 l.18 with no split allowed; or
//  (3) t is bad only for its size and c would lower the smallest angle of the triangles it
//      replaces below theirs (and below the bound): the size bound is not worth a sliver. The area
//      bound is given up there instead (the closing survey counts it).
// Refusing every worse triangle not on s left the bound unmet where it is within reach (p01.poly
// at -pYq: 16.8 degrees instead of 20); refusing those on s as well stopped
// refinement where Triangle 1.6 goes on (Constrained_Sweden -pYYq: 0.97 degrees against 1.85).
// docs/refinement.md, "-Y", has the measurements.
bool KeptBoundary::refuses(Terminator& term, const Point& c, TriangleId t) {
  const Mesh& mesh = term.mesh_;
  Predicates& pred = term.pred_;
  CavityMarks& marks = term.marks_;
  const EncroachRule& rule = term.policy_.rule;
  const double made = smallest_made_sine2(term, c);
  const double replaced = smallest_replaced_sine2(term);
  if (below_angle(made, floor_sin2_) && made < replaced) return true;  // (0)
  const double worse = std::min(bound_sin2_, replaced);
  if (below_angle(made, worse) && would_strand(term, c, worse)) return true;  // (1)
  bool touches = false;
  for (EdgeRef e : marks.boundary_subsegments()) {
    if (!keeps(mesh, e)) continue;
    touches = true;
    const Point& a = mesh.point(mesh.org(e));
    const Point& b = mesh.point(mesh.dest(e));
    if (encroaches(pred, a, b, c, rule)) return true;  // (2)
  }
  if (!touches || term.assess(t).skinny) return false;
  return below_angle(made, worse);  // (3)
}

// Would one of the triangles c makes with the cavity's boundary, with a smallest angle whose sin^2
// is below `below`, be left as it is? Its Steiner point is probed in today's mesh from the cavity
// triangle on the same edge (the new triangle lies in the cavity, which no subsegment crosses), so
// the walk meets the subsegments the new triangle's point would meet. Reads the cavity (marks)
// and leaves it as it was: the look-ahead has marks of its own.
bool KeptBoundary::would_strand(Terminator& term, const Point& c, double below) {
  const Mesh& mesh = term.mesh_;
  CavityMarks& marks = term.marks_;
  for (EdgeRef e : marks.boundary()) {
    const Point& a = mesh.point(mesh.org(e));
    const Point& b = mesh.point(mesh.dest(e));
    if (!below_angle(smallest_angle_sine2(a, b, c), below)) continue;
    const Point p = steiner_point_of(a, b, c, term.policy_.off_center_factor);
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || stranded_point(term, triangle_of(e), p)) return true;
  }
  return false;
}

// Whether the Steiner point p, probed from triangle `from`, is one no insertion can use: the
// probe finds no place for it (behind a kept subsegment or the mesh's boundary, on a vertex), or
// it lies in the lens of a kept subsegment of its cavity (refused by (2)).
bool KeptBoundary::stranded_point(Terminator& term, TriangleId from, const Point& p) {
  const Mesh& mesh = term.mesh_;
  Predicates& pred = term.pred_;
  const EncroachRule& rule = term.policy_.rule;
  const auto splittable = [&term](EdgeRef e) { return term.is_splittable(e); };
  const Probe probe = probe_candidate(term.mesh_, pred, from, p, rule, lookahead_marks_, splittable);
  if (probe.status == ProbeStatus::Unusable) return true;
  if (probe.status == ProbeStatus::Encroaches) return false;  // the subsegments split instead
  for (EdgeRef e : lookahead_marks_.boundary_subsegments())
    if (keeps(mesh, e) && encroaches(pred, mesh.point(mesh.org(e)), mesh.point(mesh.dest(e)), p, rule))
      return true;
  return false;
}

// -Y: may the interior subsegment s be split at p? plan_split left p's cavity in marks. A kept
// subsegment k on its boundary gets p as its apex; the split is refused when that triangle would be
// below the bound and worse than both the one on k now and those beside s, which the split is
// for. Otherwise a split near a corner where a long kept segment meets an interior one at a small
// angle made the triangle on the kept segment a sliver that nothing mends (drufat's la.poly
// -pYq30a0.019: 0.032 degrees, Triangle 1.6 0.043). -D needs every encroached subsegment split.
bool KeptBoundary::spoils_split(Terminator& term, EdgeRef s, const Point& p) {
  const Mesh& mesh = term.mesh_;
  CavityMarks& marks = term.marks_;
  double worse = std::min(bound_sin2_, triangle_sine2(mesh, triangle_of(s)));
  if (mesh.link[s] != kNone) worse = std::min(worse, triangle_sine2(mesh, triangle_of(mesh.link[s])));
  for (EdgeRef k : marks.boundary_subsegments()) {
    if (!keeps(mesh, k)) continue;
    const double made = smallest_angle_sine2(mesh.point(mesh.org(k)), mesh.point(mesh.dest(k)), p);
    if (made < std::min(worse, triangle_sine2(mesh, triangle_of(k)))) return true;
  }
  return false;
}

// The sin^2 of the smallest angle among the triangles that c makes with the cavity's boundary.
double KeptBoundary::smallest_made_sine2(Terminator& term, const Point& c) const {
  const Mesh& mesh = term.mesh_;
  CavityMarks& marks = term.marks_;
  double smallest = 1.0;
  for (EdgeRef e : marks.boundary())
    smallest = std::min(smallest, smallest_angle_sine2(mesh.point(mesh.org(e)), mesh.point(mesh.dest(e)), c));
  return smallest;
}

// The same for the triangles of the cavity: those with a boundary edge and the inner ones.
double KeptBoundary::smallest_replaced_sine2(Terminator& term) const {
  const Mesh& mesh = term.mesh_;
  CavityMarks& marks = term.marks_;
  double smallest = 1.0;
  for (EdgeRef e : marks.boundary()) smallest = std::min(smallest, triangle_sine2(mesh, triangle_of(e)));
  for (TriangleId u : marks.inner()) smallest = std::min(smallest, triangle_sine2(mesh, u));
  return smallest;
}

}  // namespace deltri
