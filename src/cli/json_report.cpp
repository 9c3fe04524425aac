#include "cli/json_report.h"

#include <charconv>
#include <cmath>
#include <cstdio>

#include "options/version.h"
#include "quality/statistics.h"

namespace deltri {
namespace {

// Builds the text with the right commas; keys are plain ASCII, values escaped.
class Json {
 public:
  void open(const char* key = nullptr, char bracket = '{') {
    field(key);
    out_ += bracket;
    first_ = true;
  }
  void close(char bracket = '}') {
    out_ += bracket;
    first_ = false;
  }
  void number(const char* key, double v) {
    field(key);
    if (!std::isfinite(v)) {
      out_ += "null";  // JSON has no infinity; a flat triangle's ratio is reported as null
      return;
    }
    char buffer[32];
    out_.append(buffer, std::to_chars(buffer, buffer + sizeof buffer, v).ptr);
  }
  void integer(const char* key, unsigned long long v) {
    field(key);
    out_ += std::to_string(v);
  }
  // v, or null when there is none (a bound that was not asked for).
  void optional_number(const char* key, bool present, double v) {
    if (present) return number(key, v);
    field(key);
    out_ += "null";
  }
  void string(const char* key, const std::string& v) {
    field(key);
    out_ += '"';
    for (std::size_t i = 0; i < v.size();) {
      const unsigned char c = static_cast<unsigned char>(v[i]);
      if (c == '"' || c == '\\') {
        out_ += '\\';
        out_ += static_cast<char>(c);
        ++i;
      } else if (c < 0x20) {
        escape(c);
        ++i;
      } else if (const std::size_t n = utf8_sequence(v, i)) {
        out_.append(v, i, n);
        i += n;
      } else {
        // A byte that is not part of valid UTF-8 (a file name in Latin-1, say): JSON text must be
        // UTF-8, so it is written as the character of the same number, U+0080 to U+00FF, which
        // keeps the byte and reads right for Latin-1 names.
        escape(c);
        ++i;
      }
    }
    out_ += '"';
  }
  std::string take() { return std::move(out_) + "\n"; }

 private:
  void escape(unsigned char c) {
    char buffer[8];
    std::snprintf(buffer, sizeof buffer, "\\u%04x", c);
    out_ += buffer;
  }
  // The length of the well-formed UTF-8 sequence at v[i] (Unicode's table 3-7:
  // no overlong forms, no surrogates, nothing above U+10FFFF), or 0 where there is none.
  static std::size_t utf8_sequence(const std::string& v, std::size_t i) {
    const auto at = [&](std::size_t k) { return i + k < v.size() ? static_cast<unsigned char>(v[i + k]) : 0u; };
    const unsigned c = at(0);
    const auto cont = [&](std::size_t k) { return (at(k) & 0xC0u) == 0x80u; };
    if (c < 0x80) return 1;
    if (c >= 0xC2 && c <= 0xDF) return cont(1) ? 2 : 0;
    if (c >= 0xE0 && c <= 0xEF) {
      const unsigned lo = c == 0xE0 ? 0xA0 : 0x80, hi = c == 0xED ? 0x9F : 0xBF;
      return at(1) >= lo && at(1) <= hi && cont(2) ? 3 : 0;
    }
    if (c >= 0xF0 && c <= 0xF4) {
      const unsigned lo = c == 0xF0 ? 0x90 : 0x80, hi = c == 0xF4 ? 0x8F : 0xBF;
      return at(1) >= lo && at(1) <= hi && cont(2) && cont(3) ? 4 : 0;
    }
    return 0;
  }
  void field(const char* key) {
    if (!first_) out_ += ',';
    first_ = false;
    if (key) {
      out_ += '"';
      out_ += key;
      out_ += "\":";
    }
  }
  std::string out_;
  bool first_ = true;
};

// {"<measure>": value, "x": ..., "y": ...}: a triangle named by one figure and where it is.
void triangle_at(Json& j, const char* key, const char* measure, double value, const Point& at) {
  j.open(key);
  j.number(measure, value);
  j.number("x", at.x);
  j.number("y", at.y);
  j.close();
}

}  // namespace

std::string json_report(const Mesh& mesh, const Switches& sw, const RunReport& r, int exit_status) {
  const MeshStatistics stats = compute_statistics(mesh);
  Json j;
  j.open();
  j.string("program", "deltri");
  j.string("version", version());
  j.string("command", sw.command_line);
  j.string("input", r.input_name);
  j.integer("exit_status", static_cast<unsigned long long>(exit_status));

  j.open("input_counts");
  j.integer("vertices", r.input_vertices);
  j.integer("duplicate_vertices", r.duplicates);
  if (r.pslg && r.pslg->has_segment_section) {
    j.integer("segments", r.input_segments);
    j.integer("holes", r.pslg->holes.size());
    j.integer("regions", r.pslg->regions.size());
  }
  j.close();

  j.open("mesh");
  j.integer("vertices", stats.vertices);
  j.integer("vertices_in_triangles", stats.vertices_in_triangles);
  j.integer("triangles", stats.triangles);
  j.integer("edges", stats.edges);
  j.integer("boundary_edges", stats.exterior_boundary_edges);
  j.integer("subsegments", stats.subsegments);
  // Refinement inserts Steiner points and may delete some of them again (free vertices near a
  // segment it splits): both counts, and what is left of them in the mesh.
  const unsigned long long inserted = r.refine ? r.refine->interior_steiner + r.refine->segment_steiner : 0;
  const unsigned long long deleted = r.refine ? r.refine->vertices_deleted : 0;
  j.integer("steiner_points", inserted);
  j.integer("steiner_points_deleted", deleted);
  j.integer("steiner_points_kept", inserted - deleted);
  j.close();

  j.open("quality");
  j.optional_number("min_angle_bound", sw.quality, sw.min_angle);
  j.optional_number("max_area_bound", sw.fixed_area, sw.max_area);
  j.optional_number("max_edge_length_bound", sw.user_test, sw.max_edge_length);
  // An empty mesh has no shapes: null, not 0 (which would be a real, and terrible, angle).
  const bool shapes = stats.triangles > 0;
  j.optional_number("smallest_angle", shapes, stats.smallest_angle);
  j.optional_number("largest_angle", shapes, stats.largest_angle);
  j.optional_number("smallest_area", shapes, stats.smallest_area);
  j.optional_number("largest_area", shapes, stats.largest_area);
  j.optional_number("shortest_edge", shapes, stats.shortest_edge);
  j.optional_number("longest_edge", shapes, stats.longest_edge);
  j.optional_number("largest_aspect_ratio", shapes, stats.largest_aspect_ratio);
  const auto& q = r.refine;
  // From the final mesh (quality/bound_misses.h), whatever refinement exempted or gave up on.
  const BoundMisses none;
  const BoundMisses& b = r.misses ? *r.misses : none;
  j.integer("triangles_missing_bounds", b.total);
  j.integer("triangles_below_angle_bound", b.below_angle);
  j.integer("triangles_above_size_bound", b.above_size);
  if (sw.max_angle > 0.0) j.integer("triangles_above_max_angle", b.above_max_angle);
  j.open("missing_bounds_by_cause");
  j.integer("small_input_angle", b.small_input_angle);
  if (sw.max_angle > 0.0) j.integer("large_input_angle", b.large_input_angle);
  j.integer("repaired_crossing_or_overlap", b.repaired_input);
  j.integer("double_precision", b.double_precision);
  j.integer("steiner_limits", b.steiner_limits);
  j.integer("other", b.other);
  j.close();
  j.integer("triangles_missing_bounds_not_forced_by_input", b.not_forced_by_input());
  j.integer("triangles_missing_bounds_at_input_crossings", b.at_input_crossings);
  if (sw.interior_bound != 0)
    j.integer("interior_bound_left_at_double_precision", q ? q->interior_bound_refusals : 0);
  if (sw.refinement != RefinementAlgorithm::Terminator || sw.range_restricted) {  // where the sure-fire rule applies
    j.integer("guard_refusals", q ? q->guard_refusals : 0);
    j.integer("sure_fire_refusals", q ? q->sure_fire_refusals : 0);
  }
  if (const auto& c = r.conformity) {  // -D (quality/conformity.h)
    j.open("subsegments_not_delaunay");
    j.integer("total", c->total);
    j.integer("double_precision", c->double_precision);
    j.integer("other", c->other());
    j.close();
  }
  j.open("why_missed", '[');
  if (q && q->guard_refusals > q->sure_fire_refusals) j.string(nullptr, "termination guard: points that would have made edges far below the local feature size were refused");
  if (q && q->sure_fire_refusals > 0)
    j.string(nullptr, "termination guard: subsegment splits through a small input angle were refused (Sec. 6.2's sure-fire rule)");
  if (q && q->stopped_by_max_steiner) j.string(nullptr, "the -S limit of Steiner points was reached");
  if (q && q->stopped_by_cap) j.string(nullptr, cap_explanation(*q));
  if (q && q->bad_triangles_left > 0 && sw.no_boundary_steiner > 0) j.string(nullptr, "-Y/-YY: segments were not split");
  if (q && q->bad_triangles_left > 0 && q->locked_subsegments > 0)
    j.string(nullptr, "subsegments that doubles cannot split (the split point rounds onto an end or a neighbour is flush) were left whole");
  j.close(']');
  if (q && q->skinny_left > 0) triangle_at(j, "worst_triangle", "smallest_angle", q->worst_min_angle_deg, q->worst_location);
  if (q && q->oversized_left > 0)
    triangle_at(j, "largest_triangle", "times_size_bound", q->worst_size_excess, q->worst_size_location);
  j.close();

  j.open("repairs");
  if (const auto& s = r.segments) {
    j.integer("endpoints_moved_from_duplicates", s->duplicates_remapped);
    j.integer("zero_length_segments_ignored", s->zero_length);
    j.integer("repeated_segments_ignored", s->repeated);
    j.integer("segments_split_at_vertices", s->split_at_vertices);
    j.integer("collinear_overlaps_merged", s->overlaps_merged);
    j.integer("crossings_split", s->crossings);
    j.integer("vertices_snapped_onto_segments", s->snapped);
    j.integer("segments_with_missing_endpoint_ignored", s->invalid_endpoints);
    j.integer("segments_outside_every_triangle_ignored", s->unrecovered);
  }
  if (const auto& h = r.holes) {
    j.integer("hole_points_outside_ignored", h->outside.size());
    j.integer("hole_points_on_segment_ignored", h->on_segment.size());
    if (r.regions) {
      j.integer("region_points_outside_ignored", r.regions->outside.size());
      j.integer("region_points_on_segment_ignored", r.regions->on_segment.size());
    }
  }
  j.close();

  j.open("warnings", '[');
  for (const std::string& w : run_warnings(mesh, r)) j.string(nullptr, w);
  j.close(']');

  // Up to the moment the files were written: the report is one of them.
  j.open("seconds");
  double total = 0.0;
  for (const auto& s : r.stages) {
    j.number(s.name, s.seconds);
    total += s.seconds;
  }
  j.number("total_before_writing", total);
  j.close();

  j.open("files", '[');
  for (const std::string& f : r.written) j.string(nullptr, f);
  j.close(']');
  j.close();
  return j.take();
}

}  // namespace deltri
