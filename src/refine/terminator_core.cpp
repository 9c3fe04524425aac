// The Terminator's core: Shewchuk 2001, Appendix A, Figure 38 (DELAUNAYTERMINATOR) and Figure 39
// (SPLITENCROACHEDSUBSEGMENTS, NEWVERTEX), line for line. Each bad triangle and each encroached
// subsegment gets an explicit Outcome. Where the point goes and when the guard refuses are the
// policies of terminator_policies.cpp; the queue's mechanics, prefetching and page warming are the
// driver's (terminator.cpp); l.1-2 (the constrained Delaunay triangulation, exterior removed) are
// the earlier stages'.
#include <algorithm>

#include "mesh/operations.h"
#include "refine/restore_delaunay.h"
#include "refine/terminator.h"
#include "util/invariant.h"

namespace deltri {

void Terminator::refine_all() {
  split_initial_encroachments();                             // l.3-6
  for (TriangleId t{0}; t < mesh_.triangle_slots(); ++t)  // l.7
    if (mesh_.is_live(t)) enqueue_if_bad(t);                 // l.8-9
  drain_queue();                                             // l.10-11, the driver
  mending_.run(*this);                                        // -Y/-YY: the driver
  if (policy_.retries_locks) retry_locked_encroachments();  // -D: the driver
}

// l.12-25 for one triangle from Q_t.
Outcome Terminator::split_bad_triangle(const QueuedTriangle& entry) {
  if (!is_current(mesh_, entry)) return Outcome::Gone;  // l.12
  const TriangleId t = entry.triangle;
  Assessment a = assess(t);
  if (!a.bad()) return Outcome::NotBad;
  if (!budget_left()) return Outcome::OverBudget;
  if (a.split_instead != kNone) return split_beyond_corner(a.split_instead);
  if (relocate_corners(t) && !(a = assess(t)).bad()) return Outcome::NotBad;  // a corner moved: t again
  Candidate c;
  if (const auto refusal = choose_point(t, a, c)) return *refusal;  // l.13
  const auto splittable = [this](EdgeRef e) { return is_splittable(e); };
  const Probe probe = probe_candidate(mesh_, pred_, t, c.point, policy_.candidate_rule, marks_, splittable);  // l.14
  if (probe.status == ProbeStatus::Unusable) return Outcome::Unusable;
  if (probe.status == ProbeStatus::Clear) return insert_point(t, a, c, probe);  // l.15-17
  return split_encroached_instead(entry, a, probe);                               // l.18-25
}

// l.15-17: E is empty (no splittable subsegment encroached upon).
Outcome Terminator::insert_point(TriangleId t, const Assessment& a, const Candidate& c, const Probe& probe) {
  // l.18 with a subsegment that -Y/-YY keep whole: nothing may be split, so t stays as it is
  // (counted by the closing survey).
  if (kept_.refuses_insertion(*this, c.point, t)) return Outcome::KeptBoundary;
  if (const auto refusal = guard_insertion(a, c, probe.insertion_radius)) return refused_for(t, a, *refusal);
  return insert_free_vertex(c.point, probe);
}

// l.16-17 for a point the probe found Clear.
Outcome Terminator::insert_free_vertex(const Point& p, const Probe& probe) {
  const VertexId v = add_free_vertex(p, probe.container);
  // The probe's cavity search left exactly the triangles c destroys marked.
  const InsertResult inserted =
      insert_vertex_into_cavity(mesh_, pred_, v, probe.container, probe.strictly_inside, marks_.marked());  // l.16
  if (inserted.status != InsertStatus::Inserted) {  // c sits on an unsplittable subsegment
    drop_last_vertex();
    return Outcome::OnSubsegment;
  }
  DELTRI_ASSERT(mesh_.org(inserted.edge) == v);
  new_vertex(inserted.edge, true);  // l.17
  return Outcome::Inserted;
}

// l.18-25: c encroaches upon the subsegments in probe.encroached.
Outcome Terminator::split_encroached_instead(const QueuedTriangle& entry, const Assessment& a, const Probe& probe) {
  const double d = std::sqrt(a.shape.shortest_length2);  // l.19, the alternative of Sec. 6.5
  for (EdgeRef s : probe.encroached)                     // l.20
    if (split_allowed(s, a, d)) enqueue_subsegment(s);    // l.21-22
  if (encroached_.empty()) return Outcome::Declined;  // l.23: never try t again
  // l.24-25, in the other order: t goes back only if something was split, so that a guard refusal
  // cannot repeat the same attempt forever (nothing split: an obtuse-only t's corners may move instead).
  // Splits owed to a size bound meet only the precision floor, as t itself does (floor_for).
  if (policy_.tracks_split_radii) sure_fire_parents_ = sure_fire_ancestors(a.shape.shortest);
  const std::uint64_t splits = split_encroached_subsegments(true, a.too_large);
  sure_fire_parents_ = {kNone, kNone};
  if (is_current(mesh_, entry)) splits > 0 ? enqueue_if_bad(entry.triangle) : open_obtuse_corner(entry.triangle, a);
  return Outcome::Deferred;
}

// Fig. 39 l.36-38; returns the number of subsegments split.
std::uint64_t Terminator::split_encroached_subsegments(bool queue_triangles, bool owed_to_size) {
  std::uint64_t splits = 0;
  while (!encroached_.empty()) {                            // l.36
    const EncroachedSubsegment entry = encroached_.pop();  // l.37
    const EdgeRef s = current_edge(entry);                  // l.38
    if (s == kNone) continue;
    if (!budget_left()) {
      encroached_.clear();
      break;
    }
    const Outcome outcome = split_subsegment(s, queue_triangles, owed_to_size);
    count(outcome, report_);
    splits += outcome == Outcome::Split;
  }
  return splits;
}

// Fig. 39 l.39-49 for one subsegment.
Outcome Terminator::split_subsegment(EdgeRef s, bool queue_triangles, bool owed_to_size) {
  if (!owed_to_size && bottom_.in_strip_below_an_ulp(mesh_, pred_, s)) return Outcome::Hopeless;
  prefetch_new_subsegment_homes();
  SplitPlan plan;
  if (const auto refusal = plan_split(s, owed_to_size, plan)) return *refusal;  // l.39
  if (kept_.refuses_split(*this, s, plan.point)) return Outcome::KeptBoundary;
  if (refused_by_sure_fire_rule(s, plan)) return Outcome::SureFire;
  if (policy_.deletes_before_split && free_vertices_) {  // l.40-43; else the plan stands (free_vertices_)
    s = delete_free_vertices_near(s, plan.point, queue_triangles);
    if (s == kNone) return Outcome::Gone;
    if (const auto refusal = replan_after_deletions(s, plan)) return *refusal;
  }
  const VertexId v = add_segment_vertex(plan.point, s);
  if (policy_.tracks_split_radii) {
    split_radius_.resize(v + 1, 0.0);
    split_radius_[v] = plan.radius.after_chew;
  }
  const PieceEnds piece = pieces_.of_subsegment[mesh_.subseg[s]];
  EdgeRef out = split_edge(mesh_, s, v);  // l.44
  pieces_.record_split(mesh_, v, piece);
  out = restore_delaunay_around(mesh_, pred_, v, out, plan.exactly_on);
  DELTRI_ASSERT(mesh_.org(out) == v);  // new_vertex walks v's star from out
  new_vertex(out, queue_triangles);     // l.45
  for_each_around(mesh_, out, [&](EdgeRef e) {  // l.46-49: the halves s1 and s2
    for (EdgeRef half : {e, lprev(e)})
      if (mesh_.subseg.has(half) && is_splittable(half) && is_encroached(mesh_, pred_, half, policy_.rule))
        enqueue_subsegment(half);
  });
  return Outcome::Split;
}

// Fig. 39 l.50-55; `out` leaves the new vertex.
void Terminator::new_vertex(EdgeRef out, bool queue_triangles) {
  const VertexId v = mesh_.org(out);
  finder_.note_star(mesh_, out);
  for_each_around(mesh_, out, [&](EdgeRef e) {  // l.50
    const EdgeRef opposite = lnext(e);           // l.51
    const bool segment = mesh_.has_subsegments() && mesh_.subseg.has(opposite);
    if (segment && is_splittable(opposite) &&
        encroaches(pred_, mesh_.point(mesh_.org(opposite)), mesh_.point(mesh_.dest(opposite)),
                   mesh_.point(v), policy_.rule))
      enqueue_subsegment(opposite);  // l.52-53
    else if (queue_triangles)
      enqueue_if_bad(triangle_of(e));  // l.54-55
  });
}

}  // namespace deltri
