#include "cli/surface_run.h"

#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "api/surface_pipeline.h"
#include "cli/interrupt_cleanup.h"
#include "cli/run.h"
#include "io/facet_file.h"
#include "io/output_names.h"
#include "io/output_set.h"
#include "io/surface_files.h"

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
}

std::array<Point3, 3> corners(const SurfaceMesh& m, std::size_t t) {
  const std::array<std::uint32_t, 3>& v = m.triangles[t];
  return {m.points[v[0]], m.points[v[1]], m.points[v[2]]};
}

// The smallest angle of triangle t in space, in degrees.
double smallest_angle(const SurfaceMesh& m, std::size_t t) {
  const std::array<Point3, 3> p = corners(m, t);
  double best = 180.0;
  for (int i = 0; i < 3; ++i) {
    const Point3 a = p[(i + 1) % 3] - p[i], b = p[(i + 2) % 3] - p[i];
    best = std::min(best, std::atan2(norm(cross(a, b)), dot(a, b)) * 180.0 / std::numbers::pi);
  }
  return best;
}

double smallest_angle(const SurfaceMesh& m) {
  double best = 180.0;
  for (std::size_t t = 0; t < m.triangle_count(); ++t) best = std::min(best, smallest_angle(m, t));
  return best;
}

// The guard's pass keeps the segments as they are, so bounds may be missed: say how many.
void warn_not_converged(const SurfaceMesh& m, const Switches& sw) {
  std::size_t below = 0, above = 0;
  for (std::size_t t = 0; t < m.triangle_count(); ++t) {
    below += sw.quality && smallest_angle(m, t) < sw.min_angle;
    const std::array<Point3, 3> p = corners(m, t);
    const double area = 0.5 * norm(cross(p[1] - p[0], p[2] - p[0]));
    above += sw.fixed_area && area > sw.max_area;
  }
  std::fprintf(stderr,
               "deltri: warning: the facets did not agree on their shared segments within %d rounds; meshed again "
               "with no Steiner points on segments: %zu of %zu triangles below the -q angle, %zu above the -a area\n",
               kMaxSurfaceRounds, below, m.triangle_count(), above);
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
  const SurfaceResult result = run_surface_pipeline(input, sw);
  const SurfaceMesh& mesh = result.mesh;
  const SurfaceReport& report = result.report;
  if (result.check_failed()) {
    std::fprintf(stderr, "deltri: -C: the surface mesh is not consistent; no files written\n%s", result.check->summary().c_str());
    return kExitCheck;
  }
  if (!report.converged) warn_not_converged(mesh, sw);
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
    std::fprintf(out, "Facets agreed after %d round%s (%zu facet meshes); new vertices: %zu on shared segments, %zu others\n",
                 report.rounds, report.rounds == 1 ? "" : "s", report.facet_meshings, report.shared_splits,
                 mesh.points.size() - input.points.size() - report.shared_splits);
  return kExitOk;
}

}  // namespace deltri
