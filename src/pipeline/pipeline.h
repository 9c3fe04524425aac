// The stages from an input PSLG (and, with -r, a previous mesh) to the finished mesh: Delaunay,
// segments and holes, refinement, boundary markers, the -C check, -o2 midpoints and the -j
// numbering. The one facade over the core that the command line (cli/run.cpp: files in,
// files out, messages) and the library (api/library.cpp: arrays in, arrays out) both use.
// It reads and writes no file, prints nothing and never exits: errors are exceptions
// (util/errors.h).
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "options/options.h"
#include "pipeline/run_report.h"
#include "io/ele_file.h"
#include "mesh/mesh.h"
#include "pslg/pslg.h"
#include "refine/criteria.h"
#include "refine/refine.h"
#include "refine/size_test.h"
#include "util/progress.h"

namespace deltri {

// -r: the mesh to refine, as read (.ele, and .area with a bare -a).
struct PreviousMesh {
  EleData ele;
  std::string ele_name;        // for messages: the .ele file, or the library's "triangles"
  bool area_bounds = false;    // `areas` holds one bound per triangle (<= 0: none)
  std::vector<double> areas;
};

// What the pipeline meshes, besides the Pslg itself.
struct PipelineSource {
  std::string name;                        // for messages: the input file, or the library's "input"
  bool is_poly = false;                    // segments, holes and regions apply
  const PreviousMesh* previous = nullptr;  // -r, else nullptr
  const SizeTest* size_test = nullptr;     // a caller's size test (-u's callback), else nullptr
  Progress* progress = nullptr;            // a meter's counts (util/progress.h), else nullptr
  // The wanted edge length at a point, when the size test is a size field (--size-field): only for
  // the estimate that refuses a field no memory can hold before refinement starts.
  std::function<double(const Point&)> wanted_length;
};

struct PipelineResult {
  Mesh mesh;
  std::vector<VertexId> midpoints;        // -o2: three per triangle slot (io/midpoints.h), else empty
  std::vector<std::uint32_t> numbering;   // output numbers of the vertices; empty: all, in id order
  bool check_failed = false;              // -C found faults (report.check lists them)
};

// Told the name of each stage as it ends (the command line's timings).
using StageListener = std::function<void(const char*)>;

// The bounds the switches ask for (-q, --max-angle, -a, -u), each made once; with area_file,
// per-triangle bounds are honoured (-a bare, or an .area read).
Criteria criteria_of(const Options& sw, bool area_file);

// The refinement options the switches ask for (-D, -Y, -S, -k, --queue, ...), with the criteria's
// bounds. Also the facets' (3-D).
RefineOptions refine_options(const Options& sw, const Criteria& criteria);

// Whether the switches (or a size test) ask for refinement.
bool refinement_wanted(const Options& sw, const PipelineSource& source);

// Runs every stage on `pslg`, whose vertices move into the mesh (segments, holes and regions stay
// for the writers). Fills `report`. Throws InputError (named after source.name) and MemoryError.
PipelineResult run_pipeline(Pslg& pslg, const PipelineSource& source, const Options& sw, RunReport& report,
                            const StageListener& stage = {});

}  // namespace deltri
