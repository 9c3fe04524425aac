// What a run is asked to build and write: the options the pipeline (pipeline/pipeline.h) and the
// library (api/) read. The command line's own, which name files and messages, are in Switches
// (switches.h), which extends these; the library parses Triangle's switch string into Switches
// too and keeps these.
#pragma once

#include "delaunay/triangulate.h"
#include "refine/algorithm.h"
#include "refine/quality_queue.h"
#include "refine/steiner_policy.h"

namespace deltri {

struct Options {
  // What to build.
  bool poly = false;             // -p  read a PSLG, build its constrained Delaunay triangulation
  bool refine = false;           // -r  refine a previous mesh
  bool quality = false;          // -q  quality mesh
  double min_angle = 20.0;       //     the -q angle in degrees
  bool fixed_area = false;       // -a<A>
  double max_area = -1.0;
  bool variable_area = false;    // -a  bare: regional or per-triangle areas
  bool user_test = false;        // -u<length>: no edge longer than length
  bool stock_size_test = false;  // bare -u on the command line: Triangle's stock triunsuitable (refine/size_test.h)
  bool caller_size_test = false; // a bare u in a library switch string: the caller's size function
  double max_edge_length = -1.0;
  bool circumcenters_only = false;  // -k: Steiner points at circumcentres, no off-centres
  SteinerPolicy steiner = SteinerPolicy::Automatic;  // --steiner=offcentre|circumcentre|optimal
  QueueOrder queue_order = QueueOrder::ShortestEdge;  // --queue=
  bool decline_cluster_splits = false;               // --decline-cluster-splits
  RefinementAlgorithm refinement = RefinementAlgorithm::Terminator;  // --algorithm=terminator|ruppert|chew
  int interior_bound = 0;                            // --interior-bound=1|2 (Sec. 7.2)
  double max_angle = 0.0;                            // --max-angle=A, 90 <= A < 180; 0: none
  bool range_restricted = false;                     // --range-restricted (Sec. 7.3)
  bool corner_lopping = false;                       // --corner-lopping (Sec. 6.1)
  int smooth_rounds = 0;                             // --smooth[=N]: N rounds of the improvement pass (0: none)
  bool regional_attributes = false;  // -A
  bool convex_hull = false;      // -c
  bool conforming_delaunay = false;  // -D
  bool jettison = false;         // -j
  int no_boundary_steiner = 0;   // -Y (1), -YY (2)
  long max_steiner = -1;         // -S<n>; -1 means unlimited
  bool split_segments = false;   // -s
  bool ignore_holes = false;     // -O
  bool inexact = false;          // -X (accepted; arithmetic stays exact)
  DelaunayAlgorithm algorithm = DelaunayAlgorithm::DivideAndConquer;  // -i, -l
  bool sweepline = false;        // -F (divide and conquer is used instead)

  // What to write (the library: which arrays to fill).
  bool edges = false;            // -e
  bool voronoi = false;          // -v
  bool neighbors = false;        // -n
  bool geomview = false;         // -g
  bool no_markers = false;       // -B
  bool no_poly = false;          // -P
  bool no_node = false;          // -N
  bool no_ele = false;           // -E
  bool no_iteration = false;     // -I
  bool zero_based = false;       // -z
  int order = 1;                 // -o2
  bool exact_input = false;      // --exact-input: no snapping of vertices onto nearby segments

  // How to run.
  bool check = false;            // -C
  bool quiet = false;            // -Q
  int verbose = 0;               // -V, -VV, ...
  int threads = 0;               // --threads=N; 0: all cores (threads_to_use)
  int progress = 0;              // --progress 1, --no-progress -1; 0: after 2 s of work, not with -Q
};

// The threads a run may use: --threads=N, or every core the machine reports (at least one).
int threads_to_use(const Options& options);

}  // namespace deltri
