#include "cli/report.h"

#include <cstdio>

#include "cdt/convex_hull.h"
#include "options/version.h"
#include "quality/statistics.h"
#include "quality/triangle_wording.h"
#include "refine/termination_guard.h"

namespace deltri {
namespace {

std::string plural(std::size_t n, const char* one, const char* many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

// Whether some region of the .poly bounds the area of its triangles (a bare -a uses them).
bool has_regional_area_bounds(const Pslg* pslg) {
  if (!pslg) return false;
  for (const Pslg::Region& region : pslg->regions)
    if (region.max_area > 0.0) return true;
  return false;
}

// -D: the subsegments that are not Delaunay (quality/conformity.h), by cause.
// Where the guard stopped refinement, and why when the sure-fire rule did (Ruppert, Chew and
// --range-restricted refuse splits through a small input angle, Sec. 6.2: the triangles there are
// left as the rule leaves them, not forced by the angle as the Terminator's shells would be).
std::string guard_clause(const RefineReport& q) {
  if (!q.stopped_by_guard) return "";
  if (q.sure_fire_refusals == 0) return ", where the termination guard stopped refinement";
  return ", where the termination guard stopped refinement (" + plural(q.sure_fire_refusals, "split", "splits") +
         " through a small input angle refused by the sure-fire rule of Sec. 6.2)";
}

std::string conformity_warning(const ConformityMisses& c, bool guard_stopped) {
  return plural(c.total, "subsegment is", "subsegments are") +
         " not Delaunay: -D asked for a conforming Delaunay mesh, and it is only constrained Delaunay there (" +
         std::to_string(c.double_precision) + " at the limit of double precision, " + std::to_string(c.other()) +
         (guard_stopped ? " where the termination guard refused to split them)" : " other)");
}

}  // namespace

void Messages::notice(const std::string& text) const {
  if (!sw_.quiet) std::fprintf(stderr, "deltri: %s\n", text.c_str());
}

void Messages::check_failed(const CheckReport& check) const {
  std::fprintf(stderr, "deltri: -C: the mesh is not consistent (with the paper's other algorithms this check is always on); no files written\n%s", check.summary().c_str());
}

std::vector<std::string> run_warnings(const Mesh& mesh, const RunReport& r) {
  std::vector<std::string> lines;
  const auto warn = [&](const std::string& text) { lines.push_back(text); };
  if (r.pslg) lines = r.pslg->read_warnings;  // first: each names its own file and line
  if (r.duplicates > 0) warn(plural(r.duplicates, "duplicate vertex", "duplicate vertices") + " ignored (kept the first of each)");
  if (const auto& s = r.segments) {
    if (s->duplicates_remapped) warn(plural(s->duplicates_remapped, "segment endpoint", "segment endpoints") + " moved from a duplicate vertex to the vertex it duplicates");
    if (s->zero_length) warn(plural(s->zero_length, "zero-length segment", "zero-length segments") + " ignored");
    if (s->repeated) warn(plural(s->repeated, "repeated segment", "repeated segments") + " ignored");
    if (s->split_at_vertices) warn(plural(s->split_at_vertices, "segment split", "segment splits") + " where segments pass exactly through vertices");
    if (s->overlaps_merged) warn(plural(s->overlaps_merged, "collinear overlap", "collinear overlaps") + " between segments merged");
    if (s->snapped)
      warn(plural(s->snapped, "vertex", "vertices") + " within 4 ulps of a segment placed on it (the segment split there; --exact-input keeps them off)");
    if (s->crossings) warn(plural(s->crossings, "segment crossing", "segment crossings") + " split at a new vertex");
    if (s->invalid_endpoints) warn(plural(s->invalid_endpoints, "segment", "segments") + " with a missing endpoint ignored");
    if (s->unrecovered) warn(plural(s->unrecovered, "segment", "segments") + " outside every triangle ignored");
  }
  if (const auto& h = r.holes) {
    if (!h->outside.empty()) warn(plural(h->outside.size(), "hole point", "hole points") + " outside the triangulation ignored");
    if (!h->on_segment.empty()) warn(plural(h->on_segment.size(), "hole point", "hole points") + " lying exactly on a segment ignored");
  }
  if (const auto& g = r.regions) {
    if (!g->outside.empty()) warn(plural(g->outside.size(), "region point", "region points") + " outside the triangulation ignored");
    if (!g->on_segment.empty())
      warn(plural(g->on_segment.size(), "region point", "region points") + " lying exactly on a segment ignored");
  }
  if (const auto& q = r.refine) {
    if (q->stopped_by_max_steiner) warn("refinement stopped at the -S limit of Steiner points");
    if (q->stopped_by_cap) warn(cap_explanation(*q));
    // The final mesh's count (quality/bound_misses.h), not the queue's: triangles the guard left
    // may have been cut again by later insertions, or new ones made beside them.
    const std::uint64_t left = r.misses ? r.misses->total : q->bad_triangles_left;
    if (q->bad_triangles_left > 0 && left > 0) {
      char angle[128] = "", size[128] = "";
      if (q->skinny_left > 0)
        std::snprintf(angle, sizeof angle, "worst: smallest angle %.4g degrees near (%.9g, %.9g)",
                      q->worst_min_angle_deg, q->worst_location.x, q->worst_location.y);
      if (q->oversized_left > 0)
        std::snprintf(size, sizeof size, "largest: %.4g times its size bound near (%.9g, %.9g)",
                      q->worst_size_excess, q->worst_size_location.x, q->worst_size_location.y);
      std::string both = std::string(angle) + (*angle && *size ? "; " : "") + size;
      if (q->obtuse_left > 0)
        both += (both.empty() ? "" : "; ") + std::to_string(q->obtuse_left) + " with an angle above --max-angle";
      warn(plural(left, "triangle misses", "triangles miss") + " the requested bounds" +
           guard_clause(*q) + " (" + both + ")");
    }
  }
  if (const auto& q = r.refine; q && q->interior_bound_refusals > 0)
    warn(plural(q->interior_bound_refusals, "triangle", "triangles") +
         " under the 30 degrees of --interior-bound left at the limit of double precision (Sec. 7.2 proves them for "
         "input angles of 60 degrees or more)");
  if (r.options && r.options->variable_area && !r.area_file && !has_regional_area_bounds(r.pslg))
    warn("bare -a has no effect: the input has no regional area bounds (-a<area> bounds every triangle)");
  if (const auto& b = r.misses; b && b->not_forced_by_input() > 0 && !(r.refine && r.refine->bad_triangles_left > 0))
    warn(plural(b->not_forced_by_input(), "triangle misses", "triangles miss") +
         " the requested bounds for a reason other than a small input angle (" + std::to_string(b->repaired_input) +
         " next to repaired crossings or overlaps, " + std::to_string(b->double_precision) + " at the limit of double precision, " +
         std::to_string(b->steiner_limits) + " at -S/-Y limits, " + std::to_string(b->other) + " other)");
  if (const auto& b = r.misses; b && b->at_input_crossings > 0)  // forced, yet not the input's own vertices: said
    warn(plural(b->at_input_crossings, "triangle misses", "triangles miss") +
         " the requested bounds next to crossings of input segments, forced by the angles the segments cross at");
  if (const auto& c = r.conformity; c && c->total > 0) warn(conformity_warning(*c, r.refine && r.refine->stopped_by_guard));
  if (mesh.live_triangles() == 0) {
    if (r.pslg && r.pslg->has_segment_section && mesh.vertex_count() >= 3 && r.holes && r.holes->triangles_removed > 0)
      warn("every triangle lies outside the segments or in a hole: the mesh is empty (try -c or -O)");
    else if (r.rebuilt_triangles)
      warn("-r: the .ele lists no triangles: the mesh is empty");
    else
      warn("the vertices are all collinear: no triangles");  // fewer than 3 distinct is an error
  }
  return lines;
}

void Messages::warn_about_input(const Mesh& mesh, const RunReport& r) const {
  const std::size_t from_reading = r.pslg ? r.pslg->read_warnings.size() : 0;
  const std::vector<std::string> lines = run_warnings(mesh, r);
  for (std::size_t i = 0; i < lines.size(); ++i)
    if (i < from_reading)
      std::fprintf(stderr, "deltri: warning: %s\n", lines[i].c_str());
    else
      std::fprintf(stderr, "deltri: warning: %s: %s\n", r.input_name.c_str(), lines[i].c_str());
}

void Messages::finished(const Mesh& mesh, const RunReport& r) const {
  warn_about_input(mesh, r);
  if (sw_.quiet) return;
  std::string files;
  for (const auto& w : r.written) files += " " + w;
  std::size_t used = 0;
  for (VertexId v{0}; v < mesh.vertex_count(); ++v)
    used += mesh.kind[v] != VertexKind::Duplicate && mesh.kind[v] != VertexKind::Dead;
  if (r.jettisoned_vertex_count) used = *r.jettisoned_vertex_count;
  std::string input = plural(r.input_vertices, "vertex", "vertices");
  if (r.pslg->has_segment_section) {
    input += ", " + plural(r.input_segments, "segment", "segments");
    input += ", " + plural(r.pslg->holes.size(), "hole", "holes");
  }
  std::fprintf(out_, "%s: %s -> %s, %s; wrote%s (%.3f s)\n", r.input_name.c_str(), input.c_str(),
              plural(used, "vertex", "vertices").c_str(),
              plural(mesh.live_triangles(), "triangle", "triangles").c_str(),
              files.empty() ? " nothing" : files.c_str(), r.total_seconds);
  if (sw_.triangle_messages) triangle_report(mesh, r);
  if (sw_.verbose > 0) verbose_report(mesh, r);
}

void Messages::triangle_report(const Mesh& mesh, const RunReport& r) const {
  InputCounts in;
  in.vertices = r.input_vertices;
  in.triangles = r.rebuilt_triangles;
  in.pslg = r.pslg->has_segment_section;
  in.segments = r.input_segments;
  in.holes = r.pslg->holes.size();
  const MeshStatistics stats = compute_statistics(mesh);
  std::string text = triangle_counts(in, stats, mesh.has_subsegments());
  if (sw_.verbose > 0) text += triangle_quality(stats);
  std::fprintf(out_, "%s\n", text.c_str());
}

void Messages::verbose_report(const Mesh& mesh, const RunReport& r) const {
  std::fprintf(out_, "deltri %s\n", version());
  std::fprintf(out_, "Stage timings:\n");
  for (const auto& s : r.stages) std::fprintf(out_, "  %-20s %10.4f s\n", s.name, s.seconds);
  std::fprintf(out_, "  %-20s %10.4f s\n", "total", r.total_seconds);
  std::fprintf(out_, "Input: %zu vertices (%zu duplicates)", r.input_vertices, r.duplicates);
  if (r.pslg->has_segment_section)
    std::fprintf(out_, ", %s, %s, %s", plural(r.input_segments, "segment", "segments").c_str(),
                plural(r.pslg->holes.size(), "hole", "holes").c_str(),
                plural(r.pslg->regions.size(), "region", "regions").c_str());
  std::fprintf(out_, "\n");
  const MeshStatistics stats = compute_statistics(mesh);
  std::fprintf(out_, "%s", format_statistics(stats).c_str());
  const PredicateCounters& c = r.counters;
  std::fprintf(out_, "Predicates (calls / past the filter / fully exact):\n");
  std::fprintf(out_, "  orient2d   %12llu %12llu %12llu\n", static_cast<unsigned long long>(c.orient_calls),
              static_cast<unsigned long long>(c.orient_adaptive), static_cast<unsigned long long>(c.orient_exact));
  std::fprintf(out_, "  incircle   %12llu %12llu %12llu\n", static_cast<unsigned long long>(c.incircle_calls),
              static_cast<unsigned long long>(c.incircle_adaptive), static_cast<unsigned long long>(c.incircle_exact));
  if (const auto& q = r.refine) {
    std::fprintf(out_, "Refinement:\n");
    if (r.hull_absorbed > 0)
      std::fprintf(out_, "  vertices within %g ulps of the hull taken into its chain: %zu\n", kHullAbsorbUlps,
                  r.hull_absorbed);
    std::fprintf(out_, "  Steiner points: %llu interior, %llu on segments; %llu subsegment splits; %llu free vertices deleted\n",
                static_cast<unsigned long long>(q->interior_steiner), static_cast<unsigned long long>(q->segment_steiner),
                static_cast<unsigned long long>(q->encroached_splits), static_cast<unsigned long long>(q->vertices_deleted));
    std::fprintf(out_, "  rejected Steiner points: %llu; declined splits: %llu; guard refusals: %llu ",
                static_cast<unsigned long long>(q->rejected_candidates), static_cast<unsigned long long>(q->declined_splits),
                static_cast<unsigned long long>(q->guard_refusals));
    if (q->proven_range) std::fprintf(out_, "(no guard: input angles and bound in the proven range)\n");
    else std::fprintf(out_, "(edge floor %.6g)\n", q->guard_length);
    std::fprintf(out_, "  peak bad-triangle queue: %zu; triangles still bad: %llu\n", q->peak_queue,
                static_cast<unsigned long long>(q->bad_triangles_left));
    if (q->in_parts)
      std::fprintf(out_, "  refined in %u parts apart, then seams of %llu edges: %llu Steiner points from %llu triangles\n",
                  q->parts, static_cast<unsigned long long>(q->seam_edges), static_cast<unsigned long long>(q->seam_steiner),
                  static_cast<unsigned long long>(q->seam_seeds));
    if (q->hopeless_edges > 0)
      std::fprintf(out_, "  initial edges no double can give a good triangle: %llu\n",
                  static_cast<unsigned long long>(q->hopeless_edges));
    if (q->bottom_scale_searches > 0)
      std::fprintf(out_, "  Steiner points sought among nearby doubles: %llu times, %llu with none better\n",
                  static_cast<unsigned long long>(q->bottom_scale_searches),
                  static_cast<unsigned long long>(q->bottom_scale_refusals));
    if (q->interior_bound_refusals > 0)
      std::fprintf(out_, "  triangles under the 30 degrees of --interior-bound left at the limit of double precision: %llu\n",
                  static_cast<unsigned long long>(q->interior_bound_refusals));
    if (q->sure_fire_refusals > 0)
      std::fprintf(out_, "  sure-fire refusals (splits through a small input angle, Sec. 6.2; among the guard refusals): %llu\n",
                  static_cast<unsigned long long>(q->sure_fire_refusals));
    if (q->locked_subsegments > 0)
      std::fprintf(out_, "  subsegments left whole because doubles cannot split them: %llu\n",
                  static_cast<unsigned long long>(q->locked_subsegments));
  }
  if (const auto& s = r.smooth)
    std::fprintf(out_, "Smoothing (--smooth): %s, %llu of %llu vertex moves kept\n",
                plural(static_cast<std::size_t>(s->rounds), "round", "rounds").c_str(),
                static_cast<unsigned long long>(s->moved), static_cast<unsigned long long>(s->tried));
  if (const auto& b = r.misses) {
    std::fprintf(out_, "Bounds (final mesh): %llu triangles miss them (%llu below the angle, %llu above the size",
                static_cast<unsigned long long>(b->total), static_cast<unsigned long long>(b->below_angle),
                static_cast<unsigned long long>(b->above_size));
    if (r.options && r.options->max_angle > 0.0)
      std::fprintf(out_, ", %llu above the largest angle; %llu of them between input segments at a larger angle",
                  static_cast<unsigned long long>(b->above_max_angle), static_cast<unsigned long long>(b->large_input_angle));
    std::fprintf(out_, ")\n");
    std::fprintf(out_, "  by cause: %llu next to a small input angle, %llu next to a repaired crossing or overlap, "
                "%llu at the limit of double precision, %llu at -S/-Y limits, %llu other\n",
                static_cast<unsigned long long>(b->small_input_angle), static_cast<unsigned long long>(b->repaired_input),
                static_cast<unsigned long long>(b->double_precision), static_cast<unsigned long long>(b->steiner_limits),
                static_cast<unsigned long long>(b->other));
    if (b->at_input_crossings > 0)
      std::fprintf(out_, "  of those forced by input angles, %llu at crossings of input segments\n",
                  static_cast<unsigned long long>(b->at_input_crossings));
  }
  if (const auto& c = r.conformity; c && c->total > 0)
    std::fprintf(out_, "Conforming Delaunay (-D): %llu subsegments not Delaunay (%llu at the limit of double precision, %llu other)\n",
                static_cast<unsigned long long>(c->total), static_cast<unsigned long long>(c->double_precision),
                static_cast<unsigned long long>(c->other()));
  if (r.check) std::fprintf(out_, "Consistency check (-C): %s", r.check->summary().c_str());
}

// An angle as the reports print bounds: "34", "33.5".
std::string degrees_text(double deg) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", deg);
  return text;
}

std::string cap_explanation(const RefineReport& q) {
  const std::string stopped = "refinement stopped after " + std::to_string(q.interior_steiner + q.segment_steiner) +
                              " Steiner points, the termination guard's cap";
  switch (q.cap_kind) {
    case CapKind::Cascade:
      return "refinement cannot reach this angle bound here: beyond " + degrees_text(q.first_stage_angle_deg) +
             " degrees it ran on for " + std::to_string(q.cascade_steiner_taken_back) +
             " Steiner points, the termination guard's cap, without converging; the mesh is the one that meets " +
             degrees_text(q.first_stage_angle_deg) + " degrees (" + std::to_string(q.first_stage_steiner) +
             " Steiner points)";
    case CapKind::Memory:
      return stopped + " from the memory available: a finer mesh would not fit";
    case CapKind::Stalled:
      return stopped + ": the triangles still bad for --max-angle did not fall over its last doubling of points";
    case CapKind::Work:
      break;
  }
  return stopped + " for this input (" + std::to_string(static_cast<int>(kCapPerWork)) +
         " times the points a quality mesh of its features needs): refinement is not converging here";
}

}  // namespace deltri
