#include "cli/run.h"

#include <chrono>
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <sys/stat.h>
#include <unistd.h>

#include "pipeline/pipeline.h"
#include "cli/json_report.h"
#include "cli/progress_meter.h"
#include "cli/report.h"
#include "cli/surface_run.h"
#include "io/area_file.h"
#include "io/edge_file.h"
#include "cli/interrupt_cleanup.h"
#include "io/ele_file.h"
#include "io/file_text.h"
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
#include "util/errors.h"
#include "refine/size_field.h"

namespace deltri {
namespace {

// Times the stages for the report and tells the progress meter of each.
class StageTimer {
 public:
  StageTimer(RunReport& report, ProgressMeter& meter)
      : report_(report), meter_(meter), last_(std::chrono::steady_clock::now()) {}
  void stage(const char* name, std::int64_t triangles) {
    const auto now = std::chrono::steady_clock::now();
    const double seconds = std::chrono::duration<double>(now - last_).count();
    report_.stages.push_back({name, seconds});
    meter_.stage_ended(name, seconds, triangles);
    last_ = now;
  }

 private:
  RunReport& report_;
  ProgressMeter& meter_;
  std::chrono::steady_clock::time_point last_;
};

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
  // As Triangle: -p name.node strips the extension and reads name.poly (only -r reads the .node).
  const bool poly_for_node = sw.poly && !in.refine && extension == "node";
  in.is_poly = extension == "poly" || ((extension.empty() || in.refine || poly_for_node) && sw.poly);
  const bool named_vertex_file = extension == "poly" || (extension == "node" && !poly_for_node);
  in.path = named_vertex_file ? sw.input : in.base + (in.is_poly ? ".poly" : ".node");
  return in;
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
    std::fprintf(stderr, "deltri: warning: waited for another deltri run writing the same output files\n");
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
  const MshFormat msh_format{sw.msh_version, sw.msh_binary, sw.domain_tag != 0 ? sw.domain_tag : kDomainTag};
  if (sw.msh.wanted && sw.domain_tag != 0)
    if (const std::string clash = msh_tag_clash(mesh, exp, msh_format); !clash.empty())
      throw UsageError("--domain-tag=" + std::to_string(sw.domain_tag) + ": " + clash +
                       "; choose a tag no marker uses (no files written)");
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
    add(requested_path(sw.json, out, "json"), [&mesh, &sw, &report, status](ByteSink& s) {
      const std::string text = json_report(mesh, sw, report, status);
      s.write(text.data(), text.size());
    });
  }
}

// A long option may name any file, also the one this run reads (--msh=box.poly for box.poly):
// replacing the input is never what was meant, so the outputs keep the inputs intact (the commit
// refuses an output that is one of them before writing). (Triangle's own names cannot clash with
// this run's input, -rI aside, which parse_switches refuses; an older output under them is
// replaced, as in Triangle.)
void refuse_overwriting_inputs(OutputSet& outputs, const InputFiles& in, const Pslg& pslg) {
  std::vector<std::string> names = {in.path, pslg.source_name};
  if (in.refine) names.push_back(in.base + ".ele");
  if (in.area_file) names.push_back(in.base + ".area");
  std::vector<FileId> inputs;  // each file stat'ed once
  for (std::size_t k = 0; k < names.size(); ++k) {
    struct stat st;
    const bool again = std::find(names.begin(), names.begin() + static_cast<std::ptrdiff_t>(k), names[k]) != names.begin() + static_cast<std::ptrdiff_t>(k);
    if (!again && !names[k].empty() && names[k] != "-" && stat(names[k].c_str(), &st) == 0)
      inputs.emplace_back(static_cast<std::uint64_t>(st.st_dev), static_cast<std::uint64_t>(st.st_ino));
  }
  outputs.keep_intact(std::move(inputs));
}

// Whether the .node is left out because of -I alone (it would overwrite the input's vertices; as in
// Triangle, it is still written when the vertices came from the .poly itself).
bool node_withheld_by_I(const Switches& sw, const InputFiles& in, const Pslg& pslg) {
  const bool vertices_in_poly = in.is_poly && (pslg.source_name == in.path || in.path == "-");
  return sw.no_iteration && !vertices_in_poly && !sw.no_node && !uses_standard_output(sw);
}

// With the .node withheld by -I, the .ele and .edge can name only the input's vertices: a mesh
// with vertices of its own would be written as triangles whose corners are in no file (Triangle
// writes such an .ele without a word). Refused before any work where the switches ask for new
// vertices, and, should a repair of the input have added some, before anything is written.
// (-N is not refused: leaving out the .node is then what was asked for.)
void refuse_vertices_in_no_file(const Switches& sw, const InputFiles& in, const Pslg& pslg, const Mesh* mesh,
                                std::size_t input_vertices = 0) {
  if (!node_withheld_by_I(sw, in, pslg) || (sw.no_ele && !sw.edges)) return;
  // Refinement with -S0 adds no vertex.
  const bool refines = sw.max_steiner != 0;
  const char* cause = refines && sw.quality ? "-q" : refines && (sw.fixed_area || sw.variable_area) ? "-a"
                    : refines && (sw.user_test || sw.stock_size_test) ? "-u" : refines && !sw.size_field.empty() ? "--size-field"
                    : refines && sw.conforming_delaunay ? "-D" : sw.order == 2 ? "-o2" : nullptr;
  if (!cause && mesh && mesh->vertex_count() > input_vertices) cause = "the repair of the input";
  if (!cause) return;
  const std::string node = output_base(in.base, true) + ".node";
  throw UsageError(std::string("-I: ") + cause + " adds vertices, which only a .node could hold, and -I does not write " +
                   node + " (it would replace the input's vertices); leave out -I (the outputs are then " +
                   output_base(in.base, false) + ".*) or add -N if the .node is not wanted");
}

// --size-field=FILE: FILE.node (or FILE as named) and FILE.ele, the wanted edge length the first
// vertex attribute (refine/size_field.h).
SizeField read_size_field(const std::string& name, int threads) {
  std::string extension;
  const std::string base = input_base(name, &extension);
  const std::string node_path = extension == "node" ? name : base + ".node";
  Pslg background = read_node_file(node_path, threads);
  if (background.num_attributes < 1)
    throw InputError(node_path, 0, "--size-field: the vertices have no attribute; the first one is the wanted edge length");
  const std::size_t n = background.points.size(), na = static_cast<std::size_t>(background.num_attributes);
  std::vector<double> lengths(n);
  for (std::size_t v = 0; v < n; ++v) {
    lengths[v] = background.attributes[v * na];
    if (!(lengths[v] > 0.0))
      throw InputError(node_path, 0, "--size-field: vertex " + std::to_string(v + background.first_index) +
                                         ": the wanted edge length (first attribute) must be positive, not " + std::to_string(lengths[v]));
  }
  const EleData ele = read_ele_file(base + ".ele", background.first_index, static_cast<std::uint32_t>(n), threads);
  std::vector<std::uint32_t> corners;
  for (std::uint32_t t = 0; t < ele.triangle_count(); ++t)
    for (std::uint32_t k = 0; k < 3; ++k) corners.push_back(ele.corners[t * ele.nodes_per_triangle + k]);
  return SizeField(std::vector<Point>(background.points.begin(), background.points.end()), std::move(lengths), corners);
}

// -r: the previous mesh's .ele (numbered as the .node just read) and, with a bare -a or a named
// .area, its .area bounds.
PreviousMesh read_previous_mesh(const InputFiles& in, const Pslg& pslg, int threads) {
  PreviousMesh previous;
  previous.ele_name = in.base + ".ele";
  require_regular_numbering(pslg, "the triangles of " + previous.ele_name);
  previous.ele =
      read_ele_file(previous.ele_name, pslg.first_index, static_cast<std::uint32_t>(pslg.points.size()), threads);
  previous.area_bounds = in.area_file;
  if (in.area_file) previous.areas = read_area_file(in.base + ".area", previous.ele.triangle_count(), threads);
  return previous;
}

}  // namespace

int run(const Switches& sw) {
  if (const auto facets = surface_input(sw)) return run_surface(sw, *facets);  // facets in 3-D
  RunReport report;
  report.options = &sw;
  ProgressMeter meter(sw, stderr, isatty(fileno(stderr)) != 0);
  StageTimer timer(report, meter);
  const auto start = std::chrono::steady_clock::now();
  Messages messages(sw);
  for (const std::string& notice : sw.notices) messages.notice(notice);

  const InputFiles in = input_files(sw);
  const int threads = threads_to_use(sw);  // --threads reads too
  meter.begin("read");
  Pslg pslg = in.is_poly ? read_poly_file(in.path, threads) : read_node_file(in.path, threads);
  refuse_vertices_in_no_file(sw, in, pslg, nullptr);
  PipelineSource source;
  source.name = in.path == "-" ? kStandardInputName : in.path;
  source.is_poly = in.is_poly;
  source.progress = meter.progress();
  PreviousMesh previous;
  if (in.refine) {
    previous = read_previous_mesh(in, pslg, threads);
    source.previous = &previous;
  }
  std::optional<SizeField> size_field;
  SizeTest size_test;
  if (!sw.size_field.empty()) {
    size_field.emplace(read_size_field(sw.size_field, threads));
    size_test = size_field->test();
    source.size_test = &size_test;
    source.wanted_length = [&field = *size_field](const Point& p) { return field.length_at(p); };
  }
  if (sw.stock_size_test) {  // bare -u, alongside a --size-field if both are given
    size_test = size_test ? SizeTest([field = size_test](const Point& a, const Point& b, const Point& c, double area) {
      return field(a, b, c, area) || stock_size_test(a, b, c, area);
    })
                          : SizeTest(stock_size_test);
    source.size_test = &size_test;
  }
  PipelineResult result = run_pipeline(pslg, source, sw, report, [&timer, &meter](const char* name) {
    const Progress* p = meter.progress();
    timer.stage(name, p ? p->triangles.load(std::memory_order_relaxed) : -1);
  });
  meter.begin("write");
  const Mesh& mesh = result.mesh;
  // Messages wait until the meter has stopped, so that none is written into its line.
  const auto sweepline_notice = [&] {
    if (report.sweepline_fell_back) messages.notice("-F: rounding broke the sweepline on this input; divide and conquer was used");
  };
  if (result.check_failed) {
    meter.stop();
    sweepline_notice();
    messages.check_failed(*report.check);
    return kExitCheck;
  }

  const std::vector<std::uint32_t>& numbering = result.numbering;
  // --strict: misses a small input angle does not force, subsegments -D left not Delaunay, or no
  // mesh at all.
  const bool bounds_missed = (report.misses && report.misses->not_forced_by_input() > 0) ||
                             (report.conformity && report.conformity->total > 0);
  const int status = sw.strict && (bounds_missed || mesh.live_triangles() == 0) ? kExitBounds : kExitOk;
  OutputSet outputs(OutputSet::workers_for(std::size_t{mesh.vertex_count()} + mesh.live_triangles(),
                                           static_cast<std::size_t>(threads_to_use(sw))));  // --threads writes too
  schedule_outputs(outputs, {mesh, pslg, in, sw, numbering.empty() ? nullptr : &numbering,
                             sw.order == 2 ? &result.midpoints : nullptr, report, status});
  refuse_overwriting_inputs(outputs, in, pslg);
  refuse_vertices_in_no_file(sw, in, pslg, &mesh, report.input_vertices);
  const CommitNotes notes = outputs.commit(interrupt_listener());
  timer.stage("write", -1);
  meter.stop();
  sweepline_notice();
  report_commit_notes(notes);
  report.total_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  messages.finished(mesh, report);
  return status;
}

}  // namespace deltri
