#include "cli/surface_run.h"

#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "pipeline/surface_pipeline.h"
#include "cli/interrupt_cleanup.h"
#include "cli/run.h"
#include "io/facet_file.h"
#include "io/output_names.h"
#include "io/output_set.h"
#include "surface/surface_files.h"

namespace deltri {
namespace {

std::string plural(std::size_t n, const char* one, const char* many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

void note_ignored_switches(const Switches& sw) {
  if (sw.quiet) return;
  const auto note = [](const char* what) { std::fprintf(stderr, "deltri: %s is ignored for facets in 3-D\n", what); };
  if (sw.refine) note("-r");
  if (sw.variable_area) note("-a without a number");
  if (sw.regional_attributes) note("-A");
  if (sw.convex_hull) note("-c");
  if (sw.voronoi) note("-v");
  if (sw.neighbors) note("-n");
  if (sw.order == 2) note("-o2");
  if (sw.jettison) note("-j");
  if (sw.svg.wanted) note("--svg");
  if (sw.json.wanted) note("--json");
  if (sw.strict) note("--strict");
  if (sw.stock_size_test) note("-u without a number (Triangle's stock test)");
  if (sw.domain_tag != 0) note("--domain-tag (a surface's groups are its facet markers)");
  for (const std::string& notice : sw.notices) std::fprintf(stderr, "deltri: %s\n", notice.c_str());
}

double smallest_angle(const SurfaceMesh& m) {
  double best = 180.0;
  for (const std::array<std::uint32_t, 3>& v : m.triangles)
    best = std::min(best, surface_smallest_angle(m.points[v[0]], m.points[v[1]], m.points[v[2]]));
  return best;
}

void warn(const SurfaceResult& result, const Switches& sw, int first) {
  for (const std::string& w : surface_warnings(result, sw, first)) std::fprintf(stderr, "deltri: warning: %s\n", w.c_str());
}

std::string requested(const Switches::FileRequest& r, const std::string& out, const char* extension) {
  if (r.path.empty()) return out + "." + extension;
  return r.path == "-" ? std::string(OutputSet::kStandardOutput) : r.path;
}

std::vector<std::string> schedule(OutputSet& outputs, const SurfaceMesh& mesh, const Switches& sw, const std::string& out,
                                  int first) {
  std::vector<std::string> written;
  const SurfaceWriteOptions opt{sw.zero_based ? 0 : first, !sw.no_markers};
  const auto add = [&](const std::string& name, std::function<void(ByteSink&)> produce) {
    written.push_back(name == OutputSet::kStandardOutput ? "standard output" : name);
    outputs.add_stream(name, std::move(produce));
  };
  const bool piped = uses_standard_output(sw);
  if (!piped && !sw.no_node) add(out + ".node", [&mesh, opt](ByteSink& s) { write_surface_node(s, mesh, opt); });
  if (!piped && !sw.no_ele) add(out + ".ele", [&mesh, opt](ByteSink& s) { write_surface_ele(s, mesh, opt); });
  if (!piped && (!sw.no_poly || sw.edges)) add(out + ".edge", [&mesh, opt](ByteSink& s) { write_surface_edge(s, mesh, opt); });
  if (sw.geomview) add(out + ".off", [&mesh](ByteSink& s) { write_surface_off(s, mesh); });
  if (sw.stl.wanted) add(requested(sw.stl, out, "stl"), [&mesh](ByteSink& s) { write_surface_stl(s, mesh); });
  if (sw.msh.wanted) add(requested(sw.msh, out, "msh"), [&mesh](ByteSink& s) { write_surface_msh(s, mesh); });
  if (sw.vtu.wanted) add(requested(sw.vtu, out, "vtu"), [&mesh](ByteSink& s) { write_surface_vtu(s, mesh); });
  return written;
}

}  // namespace

std::optional<std::string> surface_input(const Switches& sw) {
  if (sw.input == "-") return std::nullopt;
  std::string extension;
  const std::string base = input_base(sw.input, &extension);
  std::string path = sw.input;
  if (extension.empty() && !sw.input.ends_with(".smesh")) {
    if (!sw.poly) return std::nullopt;
    path = base + ".poly";
  } else if (extension != "poly" && !sw.input.ends_with(".smesh")) {
    return std::nullopt;
  }
  if (!is_facet_file(path)) return std::nullopt;
  return path;
}

int run_surface(const Switches& sw, const std::string& path) {
  const auto start = std::chrono::steady_clock::now();
  note_ignored_switches(sw);
  const FacetInput input = read_facet_file(path, threads_to_use(sw));
  std::FILE* progress_out = uses_standard_output(sw) ? stderr : stdout;
  SurfaceProgress progress;
  if (sw.verbose > 0 && !sw.quiet)
    progress = [progress_out](const SurfaceRound& r) {
      std::fprintf(progress_out, "Round %d: %zu facets meshed; %zu Steiner points (budget %s), %zu on shared segments; %zu facets to mesh again\n",
                   r.round, r.facets_meshed, r.steiner, r.budget < 0 ? "not set" : std::to_string(r.budget).c_str(),
                   r.shared_splits, r.to_mesh_again);
      std::fflush(progress_out);
    };
  const SurfaceResult result = run_surface_pipeline(input, sw, progress);
  const SurfaceMesh& mesh = result.mesh;
  const SurfaceReport& report = result.report;
  if (result.check_failed() && sw.check) {
    std::fprintf(stderr, "deltri: -C: the surface mesh is not consistent; no files written\n%s", result.check->summary().c_str());
    return kExitCheck;
  }
  if (result.check_failed()) {
    std::fprintf(stderr, "deltri: %s: the surface mesh is not consistent (%s; facet loops that cross other loops or segments?); no files written\n",
                 path.c_str(), result.check->one_line().c_str());
    return kExitCheck;
  }
  warn(result, sw, input.first_index);
  std::string extension;
  const std::string base = path.ends_with(".smesh") ? path.substr(0, path.size() - 6) : input_base(path, &extension);
  OutputSet outputs(OutputSet::workers_for(mesh.points.size() + mesh.triangles.size(),
                                           static_cast<std::size_t>(threads_to_use(sw))));  // --threads writes too
  const std::vector<std::string> written = schedule(outputs, mesh, sw, output_base(base, sw.no_iteration), input.first_index);
  outputs.commit(interrupt_listener());
  if (sw.quiet) return kExitOk;
  std::FILE* out = uses_standard_output(sw) ? stderr : stdout;
  std::string files;
  for (const std::string& w : written) files += " " + w;
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::fprintf(out, "%s: %s, %s, %s -> %s, %s (smallest angle %.2f); wrote%s (%.3f s)\n", path.c_str(),
               plural(input.points.size(), "point", "points").c_str(), plural(input.facets.size(), "facet", "facets").c_str(),
               plural(report.shared_segments, "shared segment", "shared segments").c_str(),
               plural(mesh.points.size(), "vertex", "vertices").c_str(),
               plural(mesh.triangle_count(), "triangle", "triangles").c_str(), smallest_angle(mesh),
               files.empty() ? " nothing" : files.c_str(), seconds);
  if (sw.verbose > 0)
    std::fprintf(out, "Facets %s after %d round%s (%zu facet meshes); new vertices: %zu on shared segments, %zu others\n",
                 report.converged ? "agreed" : "made to agree by a last pass with their segments kept", report.rounds,
                 report.rounds == 1 ? "" : "s", report.facet_meshings, report.shared_splits,
                 mesh.points.size() - input.points.size() - report.shared_splits);
  return kExitOk;
}

}  // namespace deltri
