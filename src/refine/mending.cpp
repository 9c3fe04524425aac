// -Y / -YY: mending the triangles that refinement leaves below the angle bound next to a kept
// boundary. Such a triangle's own Steiner point lies behind the kept boundary or in a kept
// subsegment's lens (kept_boundary.cpp, rule 1), so Figure 38 never inserts anything for it,
// and which vertex ends up as its apex depends on the order of earlier insertions. Most of these
// triangles are caps: a vertex close to their longest edge. A point just across that edge, inside
// the circumcircle, replaces the cap and its neighbour by triangles with that vertex and the point,
// and often by better ones (eberly-6.poly -pYq30a0.0031: the 0.29 degree cap goes, the mesh's worst
// becomes a 1.28 degree triangle elsewhere; Triangle 1.6 keeps a 0.31 degree one). So once Q_t is
// empty each such triangle, worst first, is offered a few points along and across its longest edge,
// and the best of them is inserted if every triangle it makes is better than the worst it replaces:
// the smallest angle of the mesh never falls, and each round ends at the triangles it has.
#include "refine/mending.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "geometry/constructions.h"
#include "geometry/lattice.h"
#include "refine/criteria.h"
#include "refine/kept_boundary.h"
#include "refine/terminator.h"

namespace deltri {

// A caller's size test (-u) cannot judge triangles that do not exist yet.
Mending::Mending(const RefineOptions& opt) : active_(KeptBoundary(opt).active() && opt.size_test == nullptr) {}

void Mending::run(Terminator& term) {
  if (!active_) return;
  const Mesh& mesh = term.mesh_;
  for (int round = 0; round < kMendRounds; ++round) {
    std::vector<std::pair<double, TriangleId>> worst;
    for (TriangleId t{0}; t < mesh.triangle_slots(); ++t)
      if (mesh.is_live(t) && term.assess(t).skinny) worst.emplace_back(triangle_sine2(mesh, t), t);
    std::sort(worst.begin(), worst.end());
    std::uint64_t mended = 0;
    for (const auto& [sine2, t] : worst)
      if (mesh.is_live(t) && triangle_sine2(mesh, t) == sine2 && term.budget_left()) mended += mend(term, t);
    if (mended == 0) return;
    // (nothing else: what the mending makes that still misses the bounds is counted)
  }
}

// The point across t's longest edge a-b (away from the opposite corner o) at fractions f along it
// and offsets h of its length: h = 0 is on the edge, the others in the neighbour's side of t's
// circumcircle when t is a cap.
bool Mending::mend(Terminator& term, TriangleId t) {
  const Mesh& mesh = term.mesh_;
  CavityMarks& marks = term.marks_;
  const Assessment assessed = term.assess(t);
  const auto c = mesh.corners(t);
  const unsigned i = longest_side(assessed.shape.length2);
  const Point& a = mesh.point(c[i]);
  const Point& b = mesh.point(c[(i + 1) % 3]);
  // t is counter-clockwise, so o lies left of a->b, and (dy, -dx) points right, away from it.
  const double dx = b.x - a.x, dy = b.y - a.y;
  std::optional<Point> best;
  double best_made = 0.0;
  for (double f : {0.5, 0.25, 0.75, -0.25, 1.25})
    for (double h : {0.0, 0.05, 0.1, 0.2, 0.4}) {
      const Point q{a.x + f * dx + h * dy, a.y + f * dy - h * dx};
      const double made = score(term, t, assessed, q);
      if (made > best_made) best_made = made, best = q;
    }
  if (!best) return false;
  // Probed again: marks hold the cavity of the last candidate scored, which need not be the best.
  const auto splittable = [&term](EdgeRef e) { return term.is_splittable(e); };
  const Probe probe = probe_candidate(mesh, term.pred_, t, *best, term.policy_.rule, marks, splittable);
  return term.insert_free_vertex(*best, probe) == Outcome::Inserted;
}

// The sin^2 of the smallest angle among the triangles q would make, if q may be inserted for t and
// mends: its cavity holds t, every triangle q makes is better than the worst it replaces, and q
// makes no more triangles below the angle bound, nor over the size bounds, than it replaces; else 0.
double Mending::score(Terminator& term, TriangleId t, const Assessment& assessed, const Point& q) {
  const Mesh& mesh = term.mesh_;
  CavityMarks& marks = term.marks_;
  const auto splittable = [&term](EdgeRef e) { return term.is_splittable(e); };
  const Probe probe = probe_candidate(mesh, term.pred_, t, q, term.policy_.rule, marks, splittable);
  if (probe.status != ProbeStatus::Clear || !marks.contains(t)) return 0.0;
  const Tally replaced = tally_replaced(term);
  const Tally made = tally_made(term, q, replaced.tightest_area);
  if (!(made.worst_sine2 > replaced.worst_sine2) || made.below_angle > replaced.below_angle ||
      made.over_size > replaced.over_size)
    return 0.0;
  // The rules of KeptBoundary::refuses_insertion are not asked: a point in a kept subsegment's lens, or
  // one below the floor, makes a triangle no better than the worst it replaces, refused above.
  if (term.guard_insertion(assessed, Terminator::Candidate{q}, probe.insertion_radius)) return 0.0;
  return made.worst_sine2;
}

// The cavity's triangles (marks), each once: those with a boundary edge and the inner ones.
Mending::Tally Mending::tally_replaced(Terminator& term) {
  const Mesh& mesh = term.mesh_;
  CavityMarks& marks = term.marks_;
  std::vector<TriangleId>& replaced = scratch_;
  replaced.assign(marks.inner().begin(), marks.inner().end());
  for (EdgeRef e : marks.boundary()) replaced.push_back(triangle_of(e));
  std::sort(replaced.begin(), replaced.end());
  replaced.erase(std::unique(replaced.begin(), replaced.end()), replaced.end());
  Tally tally;
  for (TriangleId u : replaced) {
    const double sine2 = triangle_sine2(mesh, u);
    const Assessment a = term.assess(u);
    tally.worst_sine2 = std::min(tally.worst_sine2, sine2);
    tally.below_angle += below_angle(sine2, term.kept_.bound_sin2());
    tally.over_size += a.too_large;
    if (const double bound = area_bound_of(mesh, u, term.rules_for(u)); bound > 0.0)
      tally.tightest_area = std::min(tally.tightest_area, bound);
  }
  return tally;
}

// The triangles q makes with the cavity's boundary, held to the global size bounds and to the
// tightest area bound of the triangles they replace.
Mending::Tally Mending::tally_made(Terminator& term, const Point& q, double tightest_area) const {
  const Mesh& mesh = term.mesh_;
  CavityMarks& marks = term.marks_;
  const SizeBounds& size = term.rules_.size;
  if (size.max_area > 0.0) tightest_area = std::min(tightest_area, size.max_area);
  Tally tally;
  for (EdgeRef e : marks.boundary()) {
    const Point& a = mesh.point(mesh.org(e));
    const Point& b = mesh.point(mesh.dest(e));
    const double sine2 = smallest_angle_sine2(a, b, q);
    tally.worst_sine2 = std::min(tally.worst_sine2, sine2);
    tally.below_angle += below_angle(sine2, term.kept_.bound_sin2());
    const double area = std::abs(triangle_area(a, b, q));
    const double longest2 = std::max({squared_distance(a, b), squared_distance(b, q), squared_distance(q, a)});
    tally.over_size += area > tightest_area ||
                       (size.max_edge_length > 0.0 && longest2 > size.max_edge_length * size.max_edge_length);
  }
  return tally;
}

}  // namespace deltri
