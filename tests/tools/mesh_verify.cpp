// deltri_mesh_verify --input IN.poly|IN.node --mesh OUTBASE [--convex-hull] [--expect-triangles N]
//                    [--no-holes] [--refined] [--min-angle Q] [--max-area A]
// Checks deltri's output OUTBASE.node/.ele (and .edge/.neigh/.poly/.v.node/.v.edge/.off when
// present) against the input.
// Prints one line per failed check and exits 1; exits 0 when everything holds, 2 on bad usage or
// an unreadable input. See verify.h and the check functions for what is verified.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "verify.h"

namespace {

struct Options {
  std::string input, mesh;
  bool convex_hull = false, no_holes = false, refined = false;
  long expect_triangles = -1;
  double min_angle = 0.0, max_area = 0.0;  // 0: not checked
};

int usage() {
  std::fprintf(stderr,
               "usage: deltri_mesh_verify --input IN.poly|IN.node --mesh OUTBASE [--convex-hull]\n"
               "                          [--expect-triangles N] [--no-holes] [--refined]\n"
               "                          [--min-angle Q] [--max-area A]\n");
  return 2;
}

bool parse(int argc, char** argv, Options& o) {
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const bool has_value = i + 1 < argc;
    if (arg == "--input" && has_value) o.input = argv[++i];
    else if (arg == "--mesh" && has_value) o.mesh = argv[++i];
    else if (arg == "--expect-triangles" && has_value) o.expect_triangles = std::atol(argv[++i]);
    else if (arg == "--convex-hull") o.convex_hull = true;
    else if (arg == "--no-holes") o.no_holes = true;
    else if (arg == "--refined") o.refined = true;
    else if (arg == "--min-angle" && has_value) o.min_angle = std::atof(argv[++i]);
    else if (arg == "--max-area" && has_value) o.max_area = std::atof(argv[++i]);
    else return false;
  }
  return !o.input.empty() && !o.mesh.empty();
}

}  // namespace

int main(int argc, char** argv) {
  Options opt;
  if (!parse(argc, argv, opt)) return usage();
  mv::Failures f;
  mv::InputPslg in;
  if (!mv::read_input(opt.input, in, f)) {
    f.print();
    return 2;
  }
  mv::OutputMesh out;
  if (!mv::read_output(opt.mesh, out, f)) {
    f.print();
    return 1;
  }
  mv::Context c(in, out);
  c.convex_hull = opt.convex_hull || !in.is_poly;
  c.no_holes = opt.no_holes;
  c.refined = opt.refined;
  if (opt.expect_triangles >= 0 && static_cast<long>(out.triangles.size()) != opt.expect_triangles)
    f.add("count", std::to_string(out.triangles.size()) + " triangles, expected " + std::to_string(opt.expect_triangles));
  mv::check_triangles_ccw(c, f);
  mv::check_edges_and_loops(c, f);
  mv::check_vertex_fans(c, f);
  mv::check_distinct_vertices(c, f);
  mv::check_input_vertices(c, f);
  mv::check_segments(c, f);
  if (opt.min_angle > 0 || opt.max_area > 0) mv::check_quality(c, f, opt.min_angle, opt.max_area);
  mv::check_boundary_edges(c, f);
  mv::check_holes(c, f);
  mv::check_constrained_delaunay(c, f);
  mv::check_point_set_cover(c, f);
  mv::check_side_files(c, f);
  mv::check_midpoints(c, f);
  mv::check_voronoi(c, f);
  mv::check_off(c, f);
  if (!f.empty()) {
    f.print();
    return 1;
  }
  std::printf("mesh_verify: ok: %zu vertices, %zu triangles, %zu input segments\n", out.points.size(),
              out.triangles.size(), in.segments.size());
  return 0;
}
