#include "delaunay/triangulate.h"

#include "delaunay/divide_and_conquer.h"
#include "delaunay/incremental.h"
#include "delaunay/sweepline.h"

namespace deltri {

DelaunayReport delaunay_triangulate(Mesh& mesh, DelaunayAlgorithm algorithm, int threads) {
  DelaunayReport report;
  if (algorithm == DelaunayAlgorithm::Incremental) {
    Predicates pred;
    incremental_delaunay(mesh, pred, report.duplicates);
    report.counters = pred.counters;
    return report;
  }
  if (algorithm == DelaunayAlgorithm::Sweepline) {
    Predicates pred;
    const bool swept = sweepline_delaunay(mesh, pred, report.duplicates);
    report.counters = pred.counters;
    if (swept) return report;
    // The duplicates are marked already; divide and conquer finds the same ones again.
    for (const auto& [duplicate, kept] : report.duplicates) mesh.kind[duplicate] = VertexKind::Input;
    report.duplicates.clear();
    report.sweepline_fell_back = true;
  }
  DivideAndConquerOptions options;
  options.alternate_cuts = algorithm == DelaunayAlgorithm::DivideAndConquer;
  options.threads = threads;
  divide_and_conquer_delaunay(mesh, options, report.duplicates, report.counters);
  return report;
}

}  // namespace deltri
