#include "cli/run.h"

#include <chrono>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "cdt/convex_hull.h"
#include "cdt/holes_and_regions.h"
#include "cdt/insert_segments.h"
#include "cdt/markers.h"
#include "cdt/rebuild_mesh.h"
#include "cli/json_report.h"
#include "cli/report.h"
#include "cli/surface_run.h"
#include "delaunay/triangulate.h"
#include "io/area_file.h"
#include "io/edge_file.h"
#include "cli/interrupt_cleanup.h"
#include "io/ele_file.h"
#include "io/file_text.h"
#include "io/midpoints.h"
#include "io/msh_file.h"
#include "io/neigh_file.h"
#include "io/node_file.h"
#include "io/off_file.h"
#include "io/output_names.h"
#include "io/output_set.h"
#include "io/poly_file.h"
#include "io/svg_file.h"
#include "io/voronoi_file.h"
#include "io/vtu_file.h"
#include "pslg/errors.h"
#include "quality/bound_misses.h"
#include "quality/check_mesh.h"
#include "refine/area_field.h"
#include "refine/refine.h"
#include "util/memory_budget.h"

namespace deltri {
namespace {

class StageTimer {
 public:
  explicit StageTimer(RunReport& report) : report_(report), last_(std::chrono::steady_clock::now()) {}
  void stage(const char* name) {
    const auto now = std::chrono::steady_clock::now();
    report_.stages.push_back({name, std::chrono::duration<double>(now - last_).count()});
    last_ = now;
  }

 private:
  RunReport& report_;
  std::chrono::steady_clock::time_point last_;
};

// The predicates are exact for every finite double (geometry/exact_integer.h), and segment
// crossings are constructed at a scale where nothing overflows, so triangulating (-p, -c, holes,
// regions) takes any finite coordinates. Refinement's constructions (circumcentres, off-centres,
// split points, lengths and areas) are plain floating point and need their squares and
// products to stay finite and normal, so refining (-q, -a, -u, -D, .area) keeps these limits.
// Distinct vertices of magnitude M differ by at least M 2^-52, so M >= 2^-150 keeps their
// differences above 2^-202.
constexpr double kLargestCoordinate = 0x1p200;   // about 1.6e60
constexpr double kSmallestMagnitude = 0x1p-150;  // about 7.0e-46

void check_coordinate_range_for_refinement(const Pslg& pslg, const std::string& path) {
  double largest = 0.0;
  const auto look = [&largest](const Point& p) { largest = std::max({largest, std::fabs(p.x), std::fabs(p.y)}); };
  for (const Point& p : pslg.points) look(p);
  // Only the vertices are ever differenced with each other: a tiny input is tiny in them.
  const double largest_vertex = largest;
  for (const Point& p : pslg.holes) look(p);
  for (const Pslg::Region& r : pslg.regions) look(r.at);
  if (largest > kLargestCoordinate) {
    char magnitude[32];
    std::snprintf(magnitude, sizeof magnitude, "%g", largest);
    throw InputError(path, 0, std::string("a coordinate of magnitude ") + magnitude +
                                  " is beyond the range supported for refinement, +-2^200 (about 1.6e60); scale the input down");
  }
  if (largest_vertex > 0.0 && largest_vertex < kSmallestMagnitude)
    throw InputError(path, 0, "every vertex coordinate is below 2^-150 (about 7.0e-46) in magnitude, too small for refinement; scale the input up");
}

// Debug builds check the mesh after every stage, so that a fault is caught in the stage that made
// it rather than at the end (or never, without -C). A fault there is a bug, not bad input.
void check_stage([[maybe_unused]] const Mesh& mesh, [[maybe_unused]] const char* stage,
                 [[maybe_unused]] bool conforming = false) {
#ifndef NDEBUG
  CheckOptions opt;
  opt.conforming = conforming;
  const CheckReport report = check_mesh(mesh, opt);
  if (!report.ok()) throw std::logic_error(std::string("inconsistent mesh after ") + stage + ": " + report.summary());
#endif
}

struct InputFiles {
  std::string base;       // name without extension, for output names
  std::string path;       // the file to read
  bool is_poly = false;   // a .poly (segments, holes, regions) rather than a .node
  bool refine = false;    // -r, or an .ele/.area named: rebuild base.ele and refine it
  bool area_file = false; // -r with a bare -a, or an .area named: read base.area
};

// Which file to read: an explicit extension decides; otherwise -p means name.poly, else name.node.
// As in Triangle, naming the .ele turns on -r and naming the .area also a bare -a.
// Standard input ("-") is a .poly with -p, else a .node; its outputs are named stdin.1.*.
InputFiles input_files(const Switches& sw) {
  InputFiles in;
  if (sw.input == "-") return {"stdin", "-", sw.poly};
  std::string extension;
  in.base = input_base(sw.input, &extension);
  in.refine = sw.refine || extension == "ele" || extension == "area";
  in.area_file = in.refine && (sw.variable_area || extension == "area");
  in.is_poly = extension == "poly" || ((extension.empty() || in.refine) && sw.poly);
  const bool named_vertex_file = extension == "poly" || extension == "node";
  in.path = named_vertex_file ? sw.input : in.base + (in.is_poly ? ".poly" : ".node");
  return in;
}

// The vertices move into the mesh (the Pslg keeps segments, holes and regions): one copy of the
// coordinates at a time is part of the memory budget.
Mesh mesh_from_pslg(Pslg& pslg) {
  Mesh mesh;
  mesh.kind.assign(pslg.points.size(), VertexKind::Input);
  mesh.points = std::move(pslg.points);
  mesh.num_attributes = pslg.num_attributes;
  mesh.attributes = std::move(pslg.attributes);
  if (pslg.has_markers) mesh.marker = std::move(pslg.markers);
  pslg.points.clear();
  return mesh;
}

// Builds the constrained Delaunay triangulation of a .poly's segments and carves the domain.
void constrain(Mesh& mesh, const Pslg& pslg, const DelaunayReport& dt, const Switches& sw,
               RunReport& report) {
  Predicates pred;
  report.segments = insert_segments(mesh, pred, pslg.segments, dt.duplicates, !sw.exact_input, sw.split_segments);
  if (sw.convex_hull) enclose_convex_hull(mesh);
  static const std::vector<Point> no_holes;
  report.holes = carve_holes(mesh, pred, sw.ignore_holes ? no_holes : pslg.holes, sw.convex_hull);
  const bool region_areas = sw.variable_area && !pslg.regions.empty();
  if (sw.regional_attributes || region_areas)
    report.regions = spread_regions(mesh, pred, pslg.regions, sw.regional_attributes, region_areas);
  report.counters.add(pred.counters);
}

// Output numbers of the vertices: every vertex but deleted ones, or with -j only those a
// triangle uses (its corners and, with -o2, its midpoints). Empty when every vertex is written in
// id order.
std::vector<std::uint32_t> vertex_numbering(const Mesh& mesh, bool jettison, const std::vector<VertexId>& midpoints) {
  std::vector<char> keep(mesh.vertex_count(), 1);
  if (jettison) {
    keep.assign(mesh.vertex_count(), 0);
    for (VertexId v : mesh.corner)
      if (v != kNone) keep[v] = 1;
    for (VertexId v : midpoints)
      if (v != kNone) keep[v] = 1;
  }
  bool all = true;
  for (VertexId v = 0; v < mesh.vertex_count(); ++v) {
    if (mesh.kind[v] == VertexKind::Dead) keep[v] = 0;
    all = all && keep[v];
  }
  std::vector<std::uint32_t> numbering;
  if (all) return numbering;
  numbering.assign(mesh.vertex_count(), kNone);
  std::uint32_t next = 0;
  for (VertexId v = 0; v < mesh.vertex_count(); ++v)
    if (keep[v]) numbering[v] = next++;
  return numbering;
}

// Where a long-option file goes: <output base>.<extension>, the name given, or standard output.
std::string requested_path(const Switches::FileRequest& r, const std::string& out, const char* extension) {
  if (r.path.empty()) return out + "." + extension;
  return r.path == "-" ? std::string(OutputSet::kStandardOutput) : r.path;
}

struct OutputContext {
  const Mesh& mesh;
  const Pslg& pslg;
  const InputFiles& in;
  const Switches& sw;
  const std::vector<std::uint32_t>* numbering;
  const std::vector<VertexId>* midpoints;  // -o2, else nullptr
  RunReport& report;
  int exit_status;
};

// Written as warnings: each means that another process touched this run's output files.
void report_commit_notes(const CommitNotes& notes) {
  if (notes.stale_temporaries_removed)
    std::fprintf(stderr, "deltri: warning: removed %zu temporary file%s left by an interrupted deltri run\n",
                 notes.stale_temporaries_removed, notes.stale_temporaries_removed == 1 ? "" : "s");
  if (notes.replaced_meanwhile)
    std::fprintf(stderr,
                 "deltri: warning: %zu output file%s changed on disk while this run was writing (another run?); "
                 "replaced by this run's set\n",
                 notes.replaced_meanwhile, notes.replaced_meanwhile == 1 ? "" : "s");
  else if (notes.waited_for_other_run)
    std::fprintf(stderr, "deltri: warning: waited for another deltri run writing to the same directory\n");
}

void schedule_outputs(OutputSet& outputs, const OutputContext& c) {
  const Mesh& mesh = c.mesh;
  const Pslg& pslg = c.pslg;
  const Switches& sw = c.sw;
  const std::vector<std::uint32_t>* numbering = c.numbering;
  const std::string out = output_base(c.in.base, sw.no_iteration);
  // As in Triangle, the input's numbering decides (-z only numbers an input whose first index is
  // neither 0 nor 1).
  const int first = pslg.numbered_by_file ? pslg.first_index : sw.zero_based ? 0 : 1;
  const bool markers = !sw.no_markers;
  const auto add = [&](const std::string& name, std::function<void(ByteSink&)> produce) {
    c.report.written.push_back(name == OutputSet::kStandardOutput ? "standard output" : name);
    outputs.add_stream(name, std::move(produce));
  };
  // A file on standard output is the result: the .node, .ele and .poly are then not written.
  const bool piped = uses_standard_output(sw);
  // With -I the .node and .poly would overwrite the input; Triangle still writes the .node when the
  // vertices came from the .poly itself (not from a .node next to it).
  const bool vertices_in_poly = c.in.is_poly && (pslg.source_name == c.in.path || c.in.path == "-");
  if (!piped && !sw.no_node && !(sw.no_iteration && !vertices_in_poly)) {
    const NodeWriteOptions opt{first, markers, numbering};
    add(out + ".node", [&mesh, opt](ByteSink& s) { write_node_file(s, mesh, opt); });
  }
  if (!piped && !sw.no_ele) {
    const EleWriteOptions opt{first, numbering, c.midpoints};
    add(out + ".ele", [&mesh, opt](ByteSink& s) { write_ele_file(s, mesh, opt); });
  }
  const bool poly_output = c.in.is_poly || sw.convex_hull;
  const std::vector<Point> holes = sw.ignore_holes ? std::vector<Point>{} : pslg.holes;
  if (!piped && poly_output && !sw.no_poly && !sw.no_iteration) {
    PolyWriteOptions opt;
    opt.first_index = first;
    opt.markers = markers;
    opt.numbering = numbering;
    // As in Triangle: the hole list is copied even with -O, the regions only when read (-A, bare -a).
    static const std::vector<Pslg::Region> no_regions;
    const std::vector<Pslg::Region>* regions = sw.regional_attributes || sw.variable_area ? &pslg.regions : &no_regions;
    add(out + ".poly", [&mesh, opt, &pslg, regions](ByteSink& s) { write_poly_file(s, mesh, opt, pslg.holes, *regions); });
  }
  if (sw.edges) {
    const EdgeWriteOptions opt{first, markers, numbering};
    add(out + ".edge", [&mesh, opt](ByteSink& s) { write_edge_file(s, mesh, opt); });
  }
  if (sw.voronoi) {
    add(out + ".v.node", [&mesh, first](ByteSink& s) { write_voronoi_node_file(s, mesh, first); });
    add(out + ".v.edge", [&mesh, first](ByteSink& s) { write_voronoi_edge_file(s, mesh, first); });
  }
  if (sw.neighbors) add(out + ".neigh", [&mesh, first](ByteSink& s) { write_neigh_file(s, mesh, first); });
  if (sw.geomview) add(out + ".off", [&mesh, numbering](ByteSink& s) { write_off_file(s, mesh, numbering); });
  const ExportOptions exp{numbering, c.midpoints, markers};
  const MshFormat msh_format{sw.msh_version, sw.msh_binary};
  if (sw.msh.wanted)
    add(requested_path(sw.msh, out, "msh"), [&mesh, exp, msh_format](ByteSink& s) { write_msh_file(s, mesh, exp, msh_format); });
  const bool vtu_binary = sw.vtu_binary;
  if (sw.vtu.wanted)
    add(requested_path(sw.vtu, out, "vtu"), [&mesh, exp, vtu_binary](ByteSink& s) { write_vtu_file(s, mesh, exp, vtu_binary); });
  if (sw.svg.wanted) {
    const SvgOptions opt{exp, first, sw.svg_numbers, holes};
    add(requested_path(sw.svg, out, "svg"), [&mesh, opt](ByteSink& s) { write_svg_file(s, mesh, opt); });
  }
  if (sw.json.wanted) {
    const RunReport& report = c.report;
    const int status = c.exit_status;
    add(requested_path(sw.json, out, "json"), [&mesh, &report, status](ByteSink& s) {
      const std::string text = json_report(mesh, report, status);
      s.write(text.data(), text.size());
    });
  }
}

// A long option may name any file, also the one this run reads (--msh=box.poly for box.poly):
// replacing the input is never what was meant. (Triangle's own names cannot clash with this run's
// input, -rI aside, which parse_switches refuses; an older output under them is replaced, as in
// Triangle.)
void refuse_overwriting_inputs(const RunReport& report, const InputFiles& in, const Pslg& pslg) {
  std::vector<std::string> inputs = {in.path, pslg.source_name};
  if (in.refine) inputs.push_back(in.base + ".ele");
  if (in.area_file) inputs.push_back(in.base + ".area");
  for (const std::string& output : report.written)
    for (const std::string& input : inputs) {
      std::error_code ec;
      if (!input.empty() && input != "-" && std::filesystem::equivalent(output, input, ec))
        throw OutputError(output + ": is an input of this run, not overwritten (no files written)");
    }
}

bool refinement_wanted(const Switches& sw, const InputFiles& in) {
  return sw.quality || sw.fixed_area || sw.variable_area || in.area_file || sw.user_test ||
         sw.conforming_delaunay;
}

// -r: the previous mesh's triangles, its .poly segments (with -p) and its .area bounds. Holes
// are not carved again and regions are not read, as in Triangle.
// The .area bounds are kept as a field over the triangles as read (refine/area_field.h), before
// the flips that make the mesh constrained Delaunay re-cut them.
void rebuild(Mesh& mesh, const Pslg& pslg, const InputFiles& in, const Switches& sw, RunReport& report,
             AreaField& area_field) {
  Predicates pred;
  const std::string ele_path = in.base + ".ele";
  require_regular_numbering(pslg, "the triangles of " + ele_path);
  const EleData ele = read_ele_file(ele_path, pslg.first_index, mesh.vertex_count());
  rebuild_mesh(mesh, pred, ele, ele_path);
  report.rebuilt_triangles = ele.triangle_count();
  if (in.is_poly) report.segments = insert_segments(mesh, pred, pslg.segments, {}, !sw.exact_input, sw.split_segments);
  protect_boundary(mesh);
  if (in.area_file) {
    mesh.area_bound = read_area_file(in.base + ".area", ele.triangle_count());
    area_field = AreaField::of(mesh);
  }
  make_constrained_delaunay(mesh, pred);
  report.counters.add(pred.counters);
}

BoundRequest bound_request(const Switches& sw, const InputFiles& in, const RunReport& report) {
  BoundRequest r;
  r.min_angle_deg = sw.quality ? sw.min_angle : 0.0;
  r.max_area = sw.fixed_area ? sw.max_area : 0.0;
  r.area_bounds = sw.variable_area || in.area_file;
  r.max_edge_length = sw.user_test ? sw.max_edge_length : 0.0;
  r.steiner_limited = report.refine && report.refine->stopped_by_max_steiner;
  r.segments_kept_whole = sw.no_boundary_steiner > 0;
  return r;
}

}  // namespace

RefineOptions refine_options(const Switches& sw, bool area_file) {
  RefineOptions opt;
  opt.quality = sw.quality;
  opt.min_angle_deg = sw.quality ? sw.min_angle : 0.0;
  opt.max_area = sw.fixed_area ? sw.max_area : 0.0;
  opt.use_triangle_area_bounds = sw.variable_area || area_file;
  opt.lenses = !sw.conforming_delaunay;
  opt.conforming_delaunay = sw.conforming_delaunay;
  opt.no_steiner_on_segments = sw.no_boundary_steiner;
  opt.max_steiner = sw.max_steiner;
  opt.off_centers = !sw.circumcenters_only;
  opt.queue_order = sw.queue_order;
  opt.decline_cluster_splits = sw.decline_cluster_splits;
  opt.max_edge_length = sw.user_test ? sw.max_edge_length : 0.0;
  opt.threads = sw.threads;
  opt.memory_budget = memory_budget();
  return opt;
}

int run(const Switches& sw) {
  if (const auto facets = surface_input(sw)) return run_surface(sw, *facets);  // facets in 3-D
  RunReport report;
  report.switches = &sw;
  StageTimer timer(report);
  const auto start = std::chrono::steady_clock::now();
  Messages messages(sw);
  for (const char* unsupported : unsupported_switches(sw))
    messages.notice(std::string(unsupported) + " is not available yet and is ignored");

  const InputFiles in = input_files(sw);
  report.input_name = in.path == "-" ? kStandardInputName : in.path;
  report.area_file = in.area_file;
  Pslg pslg = in.is_poly ? read_poly_file(in.path) : read_node_file(in.path);
  if (refinement_wanted(sw, in)) check_coordinate_range_for_refinement(pslg, pslg.source_name.empty() ? in.path : pslg.source_name);
  report.pslg = &pslg;
  report.input_vertices = pslg.points.size();
  report.input_segments = pslg.segments.size();
  timer.stage("read");

  Mesh mesh = mesh_from_pslg(pslg);
  AreaField area_field;
  if (in.refine) {
    rebuild(mesh, pslg, in, sw, report, area_field);
    timer.stage("mesh reconstruction");
    check_stage(mesh, "mesh reconstruction");
  } else {
    const DelaunayReport dt = delaunay_triangulate(mesh, sw.algorithm, sw.threads);
    report.duplicates = dt.duplicates.size();
    // As for a header of one or two vertices: duplicates merged, nothing could be triangulated.
    if (const std::size_t distinct = report.input_vertices - report.duplicates; distinct < 3)
      throw InputError(report.input_name, 0,
                       "a triangulation needs at least 3 distinct vertices; after merging duplicates the " +
                           std::to_string(report.input_vertices) + " vertices are " + std::to_string(distinct) +
                           " distinct point" + (distinct == 1 ? "" : "s"));
    report.counters.add(dt.counters);
    if (dt.sweepline_fell_back) messages.notice("-F: rounding broke the sweepline on this input; divide and conquer was used");
    timer.stage("Delaunay");
    check_stage(mesh, "Delaunay");
    if (in.is_poly) {
      constrain(mesh, pslg, dt, sw, report);
      std::vector<Pslg::Segment>().swap(pslg.segments);  // in the mesh now; refinement's peak is later
      timer.stage("segments and holes");
      check_stage(mesh, "segments and holes");
    } else if (sw.convex_hull) {
      enclose_convex_hull(mesh);
      check_stage(mesh, "convex hull");
    }
  }
  if (refinement_wanted(sw, in)) {
    if (!in.is_poly && !sw.convex_hull && !in.refine) enclose_convex_hull(mesh);  // a point set is bounded by its hull
    Predicates pred;
    if (!in.refine && (sw.convex_hull || !in.is_poly)) report.hull_absorbed = absorb_near_hull_vertices(mesh, pred);
    RefineOptions opt = refine_options(sw, in.area_file);
    opt.area_field = &area_field;
    report.refine = refine_mesh(mesh, pred, opt);
    report.counters.add(pred.counters);
    mesh.compact_triangles();
    timer.stage("refinement");
    check_stage(mesh, "refinement", sw.conforming_delaunay);
  }
  // Once, at the end: every marker follows from input markers, subsegments and the boundary.
  assign_boundary_markers(mesh, pslg.has_markers);

  if (sw.check) {
    CheckOptions opt;
    // Where the termination guard stopped refinement (its warning says so), segments may still be
    // encroached: the mesh is then held to the constrained Delaunay property only.
    const bool stopped = report.refine && (report.refine->stopped_by_guard || report.refine->stopped_by_cap);
    opt.conforming = sw.conforming_delaunay && !stopped;
    // Split points on hull edges are rounded, so a refined hull is convex only up to rounding.
    opt.convex_hull_expected = !in.is_poly && !report.refine && !in.refine;
    report.check = check_mesh(mesh, opt);
    timer.stage("check");
    if (!report.check->ok()) {
      messages.check_failed(*report.check);
      return kExitCheck;
    }
  }

  if (refinement_wanted(sw, in)) report.misses = count_bound_misses(mesh, bound_request(sw, in, report));

  std::vector<VertexId> midpoints;
  if (sw.order == 2) midpoints = add_edge_midpoints(mesh);
  const std::vector<std::uint32_t> numbering = vertex_numbering(mesh, sw.jettison, midpoints);
  if (sw.jettison)
    report.jettisoned_vertex_count = numbering.empty() ? mesh.vertex_count()
                                                       : numbering.size() - std::count(numbering.begin(), numbering.end(), kNone);
  // --strict: misses a small input angle does not force, or no mesh at all.
  const bool bounds_missed = report.misses && report.misses->not_forced_by_input() > 0;
  const int status = sw.strict && (bounds_missed || mesh.live_triangles() == 0) ? kExitBounds : kExitOk;
  OutputSet outputs;
  schedule_outputs(outputs, {mesh, pslg, in, sw, numbering.empty() ? nullptr : &numbering,
                             sw.order == 2 ? &midpoints : nullptr, report, status});
  refuse_overwriting_inputs(report, in, pslg);
  const CommitNotes notes = outputs.commit(set_interrupt_cleanup);
  report_commit_notes(notes);
  timer.stage("write");
  report.total_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  messages.finished(mesh, report);
  return status;
}

}  // namespace deltri
