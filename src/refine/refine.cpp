#include "refine/refine.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "util/errors.h"
#include "refine/area_field.h"
#include "refine/kept_boundary.h"
#include "refine/criteria.h"
#include "refine/refine_in_parts.h"
#include "util/memory_budget.h"
#include "refine/termination_guard.h"
#include "refine/terminator.h"

namespace deltri {
namespace {

// Size refinement ends with about twice the triangles its bounds ask for (Terminator's
// reserve_for_refinement): a job whose bounds need more than the memory budget can hold is refused
// before it starts, instead of refining until the memory runs out.
void refuse_impossible_size_bounds(const Mesh& mesh, const RefineOptions& opt) {
  if (!(opt.memory_budget > 0.0) && !opt.probe_memory) return;
  const double wanted = 2.0 * (triangles_wanted(mesh, opt.size) + opt.size_test_triangles);
  const double bytes = wanted * kBytesPerTriangle;
  if (asks_memory(opt) && !(bytes > kProbeAfterBytes)) return;  // a small job asks nothing
  const double budget = memory_budget_of(opt);
  if (!(budget > 0.0) || !(bytes > budget)) return;
  constexpr double kGiB = 1024.0 * 1024.0 * 1024.0;
  char text[240];
  std::snprintf(text, sizeof text,
                "the size bounds ask for about %.3g triangles, about %.3g GiB of memory; %.3g GiB are available",
                wanted, bytes / kGiB, budget / kGiB);
  throw MemoryError(text);
}

RefineReport refine_within_reach(Mesh& mesh, Predicates& pred, const RefineOptions& opt) {
  if (parts_apply(mesh, opt)) return refine_in_parts(mesh, pred, opt);
  Terminator terminator(mesh, pred, opt);
  return terminator.run();
}

std::uint64_t steiner_of(const RefineReport& r) { return r.interior_steiner + r.segment_steiner; }

// opt with what is left of its -S budget after `used` Steiner points.
RefineOptions after(const RefineOptions& opt, std::uint64_t used) {
  RefineOptions rest = opt;
  if (opt.max_steiner >= 0) rest.max_steiner = std::max<long>(0, opt.max_steiner - static_cast<long>(used));
  return rest;
}

// On at opt's bound from a mesh that meets the algorithm's reach, with at most its allowance of Steiner
// points per vertex (stage_plan). With locally optimal points the worst triangles go first (the
// paper's order) and free vertices are moved before points are added (relocation.h): served
// shortest edge first, the moves and points chased the smallest triangles down to the guard's
// floor and no corpus file reached -q40; worst first, all ten did (docs/refinement.md).
RefineReport refine_beyond_reach(Mesh& mesh, Predicates& pred, const RefineOptions& opt) {
  TerminatorStart start = TerminatorStart::of(mesh, opt);
  const auto allowance = static_cast<std::uint64_t>(stage_plan(opt).allowance * mesh.vertex_count());
  if (allowance < start.steiner_cap) {
    start.steiner_cap = allowance;
    start.cap_kind = CapKind::Cascade;
  }
  RefineOptions second = opt;
  if (opt.steiner == SteinerPolicy::Optimal && opt.queue_order == QueueOrder::ShortestEdge) second.queue_order = QueueOrder::Paper;
  return Terminator(mesh, pred, second, std::move(start)).run();
}

// Above kCascadeAngleDeg refinement can cascade (Sec. 7.3, Fig. 37): each generation of vertices
// closer together than the last (Ruppert's and Chew's algorithms from kPaperModeReachDeg). So the
// mesh is first refined to that reach (stage_plan), which refinement reaches, then on at the asked
// bound with at most its allowance of Steiner points per vertex of that mesh: where the bound can be
// met that is room enough. Where the cap stops it, the cascade
// was cut short somewhere in the middle, with triangles far worse than those it started from; a
// higher bound must not give a worse mesh, so the first stage's mesh is taken back, and the report
// counts its triangles that miss the asked bound. Either way the run ends within a small multiple
// of the first stage's size, time and memory (the copy kept is one more first-stage mesh).
RefineReport refine_in_stages(Mesh& mesh, Predicates& pred, const RefineOptions& opt) {
  const double reach_deg = stage_plan(opt).reach_deg;
  if (!asks_beyond(opt.angle, reach_deg)) return refine_within_reach(mesh, pred, opt);
  RefineOptions reach = opt;
  reach.angle = AngleBound(reach_deg);
  const RefineReport first = refine_within_reach(mesh, pred, reach);
  Mesh first_mesh = mesh;
  RefineReport report = refine_beyond_reach(mesh, pred, after(opt, steiner_of(first)));
  if (report.stopped_by_cap) {
    mesh = std::move(first_mesh);
    RefineReport taken_back = Terminator(mesh, pred, opt).finish();  // the first stage's mesh against opt's bound
    add_counts(taken_back, first);
    taken_back.stopped_by_cap = true;
    taken_back.steiner_cap = report.steiner_cap;
    taken_back.cap_kind = report.cap_kind;
    taken_back.cascade_steiner_taken_back = steiner_of(report);
    report = taken_back;
  } else {
    add_counts(report, first);
  }
  report.in_two_stages = true;
  report.first_stage_steiner = steiner_of(first);
  report.first_stage_angle_deg = reach_deg;
  return report;
}

// Each triangle's entry in mesh.area_bound becomes the bound refinement held it to (area_bound_of:
// that of the initial triangle its centroid lies in, refine/area_field.h). The entries handed on by
// slot can differ, and the quality account (quality/bound_misses.h) reads them: one bound for both.
void record_field_bounds(Mesh& mesh, const AreaField& field) {
  Criteria held;
  held.size.triangle_bounds = true;
  held.area_field = &field;
  for (TriangleId t{0}; t < mesh.triangle_slots(); ++t)
    if (mesh.is_live(t)) mesh.area_bound[t] = area_bound_of(mesh, t, held);
}

}  // namespace

double memory_budget_of(const RefineOptions& opt) {
  return asks_memory(opt) ? memory_budget() : opt.memory_budget;
}

RefineReport refine_mesh(Mesh& mesh, Predicates& pred, const RefineOptions& asked) {
  refuse_impossible_size_bounds(mesh, asked);
  const bool given = asked.area_field != nullptr && !asked.area_field->empty();
  const AreaField field = asked.size.triangle_bounds && !given ? AreaField::of(mesh) : AreaField{};
  RefineOptions opt = asked;
  opt.steiner = opt.off_centers ? resolved_policy(asked.steiner, asked.angle.degrees(), keeps_boundary(asked))
                                : SteinerPolicy::Circumcentre;
  if (!given) opt.area_field = &field;
  const RefineReport report = refine_in_stages(mesh, pred, opt);
  if (!opt.area_field->empty() && mesh.area_bound.size() == mesh.triangle_slots())
    record_field_bounds(mesh, *opt.area_field);
  return report;
}

void add_counts(RefineReport& to, const RefineReport& from) {
  for (std::uint64_t RefineWork::*count : kWorkCounts) to.*count += from.*count;
  to.hopeless_edges = std::max(to.hopeless_edges, from.hopeless_edges);  // both count the same initial edges
  to.stopped_by_guard = to.stopped_by_guard || from.stopped_by_guard;
  to.stopped_by_max_steiner = to.stopped_by_max_steiner || from.stopped_by_max_steiner;
  to.stopped_by_cap = to.stopped_by_cap || from.stopped_by_cap;
}

}  // namespace deltri
