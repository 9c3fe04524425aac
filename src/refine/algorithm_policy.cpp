#include "refine/algorithm_policy.h"

#include "refine/refine.h"

namespace deltri {

AlgorithmPolicy AlgorithmPolicy::of(const RefineOptions& opt) {
  AlgorithmPolicy policy;
  switch (opt.algorithm) {
    case RefinementAlgorithm::Terminator: policy = terminator_algorithm(opt); break;
    case RefinementAlgorithm::Ruppert: policy = ruppert_algorithm(opt); break;
    case RefinementAlgorithm::Chew: policy = chew_algorithm(opt); break;
  }
  if (opt.range_restricted) restrict_split_ranges(policy);
  policy.interior_strategy = opt.interior_bound;
  policy.declines_cluster_splits = opt.decline_cluster_splits;
  return policy;
}

StagePlan stage_plan(const RefineOptions& opt) { return stage_plan(opt.algorithm); }

}  // namespace deltri
