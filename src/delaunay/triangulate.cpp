#include "delaunay/triangulate.h"

#include "delaunay/divide_and_conquer.h"
#include "delaunay/incremental.h"

namespace deltri {

DelaunayReport delaunay_triangulate(Mesh& mesh, DelaunayAlgorithm algorithm, int threads) {
  DelaunayReport report;
  if (algorithm == DelaunayAlgorithm::Incremental) {
    Predicates pred;
    incremental_delaunay(mesh, pred, report.duplicates);
    report.counters = pred.counters;
    return report;
  }
  DivideAndConquerOptions options;
  options.alternate_cuts = algorithm == DelaunayAlgorithm::DivideAndConquer;
  options.threads = threads;
  divide_and_conquer_delaunay(mesh, options, report.duplicates, report.counters);
  return report;
}

}  // namespace deltri
