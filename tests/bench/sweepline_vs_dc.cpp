// make bench: Fortune's sweepline (-F) against divide and conquer and incremental insertion on a
// million points (uniform, a shuffled 1000 x 1000 grid, gaussian), in memory. Prints each
// algorithm's time and whether the sweepline and incremental insertion gave divide and conquer's
// triangles: the same set, cocircular ties included (all three break them by
// Predicates::incircle_perturbed). Exit status 1 if they did not.
//   deltri_sweepline_vs_dc [N] [--no-incremental]      (N points per set, default 1000000)
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
  const auto expected = meshcheck::triangle_set(dc);
  const bool same_sweep = !rsw.sweepline_fell_back && meshcheck::triangle_set(sweep) == expected;
  double t_inc = -1.0;
  bool same_inc = true;
  if (with_incremental) {
    Mesh inc = meshcheck::mesh_of(pts);
    DelaunayReport rinc;
    t_inc = seconds(inc, DelaunayAlgorithm::Incremental, rinc);
    same_inc = meshcheck::triangle_set(inc) == expected;
  }
  const bool delaunay = meshcheck::delaunay_faults(sweep) == 0 && meshcheck::all_faults(sweep) == 0;
  std::printf("| %s | %zu | %u | %.3f | %.3f | %s | %s | %s | %s |\n", name, pts.size(), sweep.live_triangles(), t_dc, t_sw,
              t_inc < 0 ? "-" : std::to_string(t_inc).substr(0, 5).c_str(),
              rsw.sweepline_fell_back ? "fell back" : same_sweep ? "identical" : "DIFFERENT",
              !with_incremental ? "-" : same_inc ? "identical" : "DIFFERENT", delaunay ? "yes" : "NO");
  return same_sweep && same_inc && delaunay;
}

}  // namespace

int main(int argc, char** argv) {
  const std::size_t n = argc > 1 ? std::strtoul(argv[1], nullptr, 10) : 1000000;
  const bool incremental = argc <= 2 || std::string(argv[2]) != "--no-incremental";
  const int side = static_cast<int>(std::lround(std::sqrt(static_cast<double>(n))));
  std::printf("| points | n | triangles | divide and conquer s | sweepline (-F) s | incremental (-i) s | -F against D&C | -i against D&C | -F Delaunay |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|\n");
  bool ok = compare("uniform", meshcheck::uniform(n, 1), incremental);
  ok = compare("grid", meshcheck::shuffled_grid(side, side, 2), incremental) && ok;
  ok = compare("gaussian", meshcheck::gaussian(n, 3), incremental) && ok;
  return ok ? 0 : 1;
}
