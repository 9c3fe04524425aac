// What a run did: filled by the pipeline (pipeline.h), read by the command line's messages and JSON
// report (cli/report.h, cli/json_report.h) and by the library's outputs.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "cdt/holes_and_regions.h"
#include "cdt/insert_segments.h"
#include "geometry/predicates.h"
#include "improve/smooth.h"
#include "options/options.h"
#include "pslg/pslg.h"
#include "quality/bound_misses.h"
#include "quality/check_mesh.h"
#include "quality/conformity.h"
#include "refine/refine.h"

namespace deltri {

struct RunReport {
  struct Stage {
    const char* name;
    double seconds;
  };
  const Options* options = nullptr;  // what the run was asked
  const Pslg* pslg = nullptr;
  std::string input_name;
  std::size_t input_vertices = 0;
  std::size_t input_segments = 0;  // pslg's, whose list is released once the segments are in
  std::vector<Stage> stages;
  std::size_t duplicates = 0;
  std::optional<std::size_t> rebuilt_triangles;  // -r: the triangles of the .ele read
  std::optional<SegmentReport> segments;
  std::optional<HoleReport> holes;
  std::optional<RegionReport> regions;
  std::optional<CheckReport> check;
  std::optional<RefineReport> refine;
  std::optional<SmoothReport> smooth;  // --smooth
  bool area_file = false;         // per-triangle area bounds were read (-r with a bare -a, or a .area)
  std::optional<BoundMisses> misses;  // the final mesh against the -q/-a/-u bounds, when any was asked
  std::optional<ConformityMisses> conformity;  // -D: the subsegments that are not Delaunay
  // -j: the vertices the .node lists (those some triangle uses, -o2 midpoints included), which the
  // summary reports instead of every vertex of the mesh.
  std::optional<std::size_t> jettisoned_vertex_count;
  bool sweepline_fell_back = false;  // -F: rounding broke the sweep; divide and conquer was used
  std::size_t hull_absorbed = 0;  // vertices taken into the hull chain (absorb_near_hull_vertices)
  PredicateCounters counters;
  std::vector<std::string> written;
  double total_seconds = 0.0;
};

}  // namespace deltri
