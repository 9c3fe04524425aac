// make bench: Fortune's sweepline (-F) against divide and conquer and incremental insertion on a
// million points (uniform, a shuffled 1000 x 1000 grid, gaussian), in memory. Prints each
// algorithm's time and whether the sweepline gave divide and conquer's triangulation: the same
// triangles where no four points are cocircular, and otherwise the same edges away from cocircular
// ties (tests/mesh/mesh_checks.h, firm_edges). Exit status 1 if it did not.
//   deltri_sweepline_vs_dc [N]      (N points per set, default 1000000)
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "delaunay/triangulate.h"
#include "mesh/mesh_checks.h"

using namespace deltri;

namespace {

double seconds(Mesh& m, DelaunayAlgorithm algorithm, DelaunayReport& report) {
  const auto start = std::chrono::steady_clock::now();
  report = delaunay_triangulate(m, algorithm, 1);
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

bool compare(const char* name, const std::vector<Point>& pts, bool with_incremental) {
  Mesh dc = meshcheck::mesh_of(pts), sweep = meshcheck::mesh_of(pts);
  DelaunayReport rdc, rsw;
  const double t_dc = seconds(dc, DelaunayAlgorithm::DivideAndConquer, rdc);
  const double t_sw = seconds(sweep, DelaunayAlgorithm::Sweepline, rsw);
  double t_inc = -1.0;
  if (with_incremental) {
    Mesh inc = meshcheck::mesh_of(pts);
    DelaunayReport rinc;
    t_inc = seconds(inc, DelaunayAlgorithm::Incremental, rinc);
  }
  const bool same_triangles = meshcheck::triangle_set(dc) == meshcheck::triangle_set(sweep);
  const bool same_firm = meshcheck::firm_edges(dc) == meshcheck::firm_edges(sweep);
  const bool delaunay = meshcheck::delaunay_faults(sweep) == 0 && meshcheck::all_faults(sweep) == 0;
  std::printf("| %s | %zu | %u | %.3f | %.3f | %s | %s | %s |\n", name, pts.size(), sweep.live_triangles(), t_dc, t_sw,
              t_inc < 0 ? "-" : std::to_string(t_inc).substr(0, 6).c_str(),
              rsw.sweepline_fell_back ? "fell back" : same_triangles ? "identical" : same_firm ? "same up to cocircular ties" : "DIFFERENT",
              delaunay ? "yes" : "NO");
  return !rsw.sweepline_fell_back && same_firm && delaunay && dc.live_triangles() == sweep.live_triangles();
}

}  // namespace

int main(int argc, char** argv) {
  const std::size_t n = argc > 1 ? std::strtoul(argv[1], nullptr, 10) : 1000000;
  const bool incremental = argc <= 2 || std::string(argv[2]) != "--no-incremental";
  const int side = static_cast<int>(std::lround(std::sqrt(static_cast<double>(n))));
  std::printf("| points | n | triangles | divide and conquer s | sweepline (-F) s | incremental (-i) s | -F against D&C | -F Delaunay |\n");
  std::printf("|---|---|---|---|---|---|---|---|\n");
  bool ok = compare("uniform", meshcheck::uniform(n, 1), incremental);
  ok = compare("grid", meshcheck::shuffled_grid(side, side, 2), incremental) && ok;
  ok = compare("gaussian", meshcheck::gaussian(n, 3), incremental) && ok;
  return ok ? 0 : 1;
}
