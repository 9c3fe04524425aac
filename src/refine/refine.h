// Delaunay refinement: the Terminator of Shewchuk 2001 (Sec. 6.3-6.5, Appendix A, Figs. 38-39),
// with diametral lenses by default, concentric-shell segment splitting, off-centres, and a
// termination guard for angle bounds beyond the proven range.
//
// Input: a constrained Delaunay triangulation whose exterior triangles and holes are gone, with
// subsegments on the segment edges (a segment-bounded domain), possibly with markers, triangle
// attributes and area bounds. Output: a constrained Delaunay triangulation (a conforming Delaunay
// one with conforming_delaunay) in which every triangle meets the bounds, except where the report
// says otherwise.
//
// With lenses, the free vertices inside a subsegment's diametral circle are deleted before it is
// split (Chew; Fig. 39 l.40-43, mesh/delete_vertex.h).
#pragma once

#include <array>
#include <cstdint>
#include <iterator>
#include <vector>

#include "geometry/mesh_bounds.h"
#include "geometry/point.h"
#include "geometry/predicates.h"
#include "mesh/mesh.h"
#include "refine/algorithm.h"
#include "refine/quality_queue.h"
#include "refine/size_test.h"
#include "refine/steiner_policy.h"

namespace deltri {

class AreaField;
struct Progress;

struct RefineOptions {
  AngleBound angle;                     // theta (-q), and what refinement derives from it
  SizeBounds size;                      // -a, -u (mesh.area_bound for -a alone, regions, .area)
  LargestAngleBound max_angle;          // --max-angle
  bool lenses = true;                   // false with -D: diametral circles
  bool conforming_delaunay = false;     // -D: the result must be Delaunay, not only constrained
  int no_steiner_on_segments = 0;       // 0, 1 = not on boundary segments (-Y), 2 = none (-YY)
  long max_steiner = -1;                // -S; -1 unlimited
  bool off_centers = true;              // Ungor's off-centres instead of circumcentres
  // --steiner: off-centres, circumcentres or locally optimal points (refine/steiner_policy.h);
  // refine_mesh resolves Automatic by the asked angle bound, for every stage alike.
  SteinerPolicy steiner = SteinerPolicy::Automatic;
  // A caller's size test (refine/size_test.h), or null. Its wishes are unknown in advance, so only
  // the memory budget caps the Steiner points, and refinement stays on one thread (refine_in_parts.h).
  const SizeTest* size_test = nullptr;
  // The triangles the size test is known to ask for (a size field's estimate), added to the size
  // bounds' own in the up-front refusal of bounds beyond the memory (0: unknown).
  double size_test_triangles = 0.0;
  QueueOrder queue_order = QueueOrder::ShortestEdge;  // which bad triangle goes first (quality_queue.h)
  // Fig. 38 l.21: let SPLITPERMITTED decline cluster splits. That is the Terminator's proof of
  // termination, but a declined triangle keeps its angle (up to Theorem 12's bound) wherever it
  // is, even far out along a long cluster subsegment. Off (the default), every encroached
  // subsegment is split as in Triangle; the isosceles shell triangles at a junction are exempt
  // instead (Miller-Pav-Walkington), and the guard still bounds every new edge.
  bool decline_cluster_splits = false;
  // --algorithm (refine/algorithm.h): the Terminator, Ruppert's algorithm (Sec. 3) or Chew's second
  // algorithm (Sec. 4), each as the policies the one core asks.
  RefinementAlgorithm algorithm = RefinementAlgorithm::Terminator;
  // --interior-bound (Sec. 7.2), with Ruppert or Chew: 0 none; 1: B = 1 (30 degrees) for the
  // triangles with no vertex in a segment interior, the -q bound for the others; 2: every triangle
  // under 30 degrees is split, but one that meets -q has its encroached subsegments split only where
  // the midpoint's insertion radius (half the subsegment) is at least its shortest edge.
  int interior_bound = 0;
  // Sec. 7.3: range-restricted segment splitting (refine/range_restricted.h). Off: midpoints,
  // shells and mirrored splits as before.
  bool range_restricted = false;
  // --corner-lopping (Sec. 6.1, cdt/corner_lopping.h): by vertex id, 1 for an apex whose fans fill
  // lopped corners, 2 for a shield vertex; the sectors (apex, shield vertex, next shield vertex
  // counter-clockwise, sorted by apex) whose triangles at the apex are left alone. A subsegment
  // from an apex to a shield vertex is never split.
  const std::vector<char>* lopped_apices = nullptr;
  const std::vector<std::array<VertexId, 3>>* lopped_sectors = nullptr;
  // -r: the mesh and its segments are an earlier run's, whose segment splits are input vertices
  // now; its straight chains of subsegments are segment pieces (straight_chain_vertices in
  // refine/segment_pieces.h), as they were in that run. Off for a first run, whose pieces are its
  // subsegments as given.
  bool straight_chains = false;
  // With straight_chains: only the chains that end at a sharp junction (a first run's .poly,
  // SegmentPieces), so that other inputs' collinear vertices keep their own pieces.
  bool straight_chains_at_sharp_junctions_only = false;
  // > 1: a second thread faults in the growing arrays' pages (util/page_warmer.h) and the halves
  // run at once. The mesh does not depend on it.
  int threads = 1;
  // Refine a large mesh as two halves and the seam between them (refine/refine_in_parts.h), on one thread
  // or two: a rule of the input and this switch, so the mesh is the same for every thread count.
  bool in_parts = true;
  // The rule for the number of parts (refine/refine_in_parts.h, part_depth): a mesh with this many live
  // triangles is cut once, one with 8 times as many twice (4 parts), 64 times three times, ...
  // Tests lower it to cut small meshes deeply; the program keeps the default.
  std::uint32_t part_min_triangles = 20000;
  // The memory refinement may use, in bytes (0: no limit): size bounds that need more are refused
  // before refinement starts (MemoryError), and the Steiner cap never allows more
  // (termination_guard.h).
  double memory_budget = 0.0;
  // With memory_budget 0: ask the machine for it (util/memory_budget.h), but only once the run
  // may need it (termination_guard.h, kProbeAfterSteiner): a small run asks nothing. The command
  // line and the library set it.
  bool probe_memory = false;
  // The field of bounds that vary within a region (refine/area_field.h), built from the mesh as
  // the caller read it (-r: before it was made constrained Delaunay); if null or empty,
  // refine_mesh builds one from the mesh it is given.
  const AreaField* area_field = nullptr;
  // Where refinement publishes its counts for a progress meter (util/progress.h), or null: the
  // library's default. Publishing never changes the mesh.
  Progress* progress = nullptr;
};

// What set the Steiner cap (termination_guard.h).
enum class CapKind : std::uint8_t {
  Work,     // the feature work of the input and the size bounds
  Cascade,  // beyond kCascadeAngleDeg: an allowance per vertex of the mesh refined to that angle
  Memory,   // the memory budget
  Stalled,  // --max-angle beyond -q: the bad triangles did not fall over a doubling of the points
};

// The counts of work done that add up over the parts of one refinement (stages, halves): only
// std::uint64_t counters, each listed in kWorkCounts below, which add_counts sums.
struct RefineWork {
  std::uint64_t interior_steiner = 0;     // free vertices inserted (circumcentres, off-centres)
  std::uint64_t segment_steiner = 0;      // vertices inserted on subsegments
  std::uint64_t vertices_deleted = 0;     // free vertices deleted before a split (Chew; Fig. 39 l.40)
  std::uint64_t encroached_splits = 0;    // subsegment splits
  std::uint64_t rejected_candidates = 0;  // Steiner points rejected because they encroach
  std::uint64_t declined_splits = 0;      // rejected points whose subsegments SPLITPERMITTED kept
  std::uint64_t guard_refusals = 0;       // insertions refused by the termination guard
  std::uint64_t kept_boundary_refusals = 0;  // points refused: they encroach upon a subsegment -Y/-YY keep
  std::uint64_t locked_subsegments = 0;   // subsegments left unsplit: doubles could not split them
  std::uint64_t bottom_scale_searches = 0;  // Steiner points chosen among nearby doubles (bottom_scale.h)
  std::uint64_t bottom_scale_refusals = 0;  // of those, triangles no nearby double improved
  std::uint64_t interior_bound_refusals = 0;  // Sec. 7.2: triangles bad only for its 30 degrees, left at the bottom scale
  std::uint64_t sure_fire_refusals = 0;  // Ruppert, Chew: splits refused by Sec. 6.2's rule (also guard refusals)
};

// Every counter of RefineWork, once: the static_assert fails when a counter is added to the struct
// and not here, so the sum cannot silently miss one.
inline constexpr std::uint64_t RefineWork::*kWorkCounts[] = {
    &RefineWork::interior_steiner,       &RefineWork::segment_steiner,        &RefineWork::vertices_deleted,
    &RefineWork::encroached_splits,      &RefineWork::rejected_candidates,    &RefineWork::declined_splits,
    &RefineWork::guard_refusals,         &RefineWork::kept_boundary_refusals, &RefineWork::locked_subsegments,
    &RefineWork::bottom_scale_searches,  &RefineWork::bottom_scale_refusals,  &RefineWork::interior_bound_refusals,
    &RefineWork::sure_fire_refusals,
};
static_assert(sizeof(RefineWork) == std::size(kWorkCounts) * sizeof(std::uint64_t),
              "every RefineWork counter must be listed in kWorkCounts");

struct RefineReport : RefineWork {
  std::uint64_t hopeless_edges = 0;         // initial edges no double can give a good triangle
  bool stopped_by_guard = false;
  bool stopped_by_max_steiner = false;
  bool stopped_by_cap = false;            // the guard's Steiner point cap was reached
  std::uint64_t steiner_cap = 0;
  CapKind cap_kind = CapKind::Work;
  // Refined to the algorithm's single-stage reach first, then on at the asked bound (refine.cpp): the Steiner points
  // of that first stage.
  // If the cap stopped the second stage, its mesh was dropped for the first's: the Steiner points
  // it had inserted.
  bool in_two_stages = false;
  std::uint64_t first_stage_steiner = 0;
  double first_stage_angle_deg = 0.0;  // the bound of that first stage
  std::uint64_t cascade_steiner_taken_back = 0;
  double guard_length = 0.0;              // the edge-length floor used (0: none)
  bool proven_range = false;              // the guard was off: the paper's theorems cover the run
  // Triangles still bad afterwards (angle below theta, not between two subsegments, or too large).
  std::uint64_t bad_triangles_left = 0;
  std::uint64_t skinny_left = 0;          // of those, the ones with an angle below theta
  double worst_ratio = 0.0;               // circumradius / shortest edge of the worst skinny one
  double worst_min_angle_deg = 0.0;       // its smallest angle
  Point worst_location;                   // its centroid
  std::uint64_t oversized_left = 0;       // the ones over a size bound
  std::uint64_t obtuse_left = 0;          // the ones with an angle above --max-angle
  double worst_size_excess = 0.0;         // the largest size_excess (refine/criteria.h)
  Point worst_size_location;              // that triangle's centroid
  std::size_t peak_queue = 0;             // bad-triangle queue
  // Refined in two halves at once (refine/refine_in_parts.h): the seam's edges (none when the halves do not
  // touch), its Terminator's Steiner points and the triangles it started from.
  bool in_parts = false;
  std::uint32_t parts = 0;                // the parts refined apart (2^d, fewer where a part could not be cut)
  std::uint64_t seam_edges = 0;
  std::uint64_t seam_steiner = 0;
  std::uint64_t seam_seeds = 0;
};

// Throws MemoryError (util/errors.h) when the size bounds ask for more triangles than
// opt.memory_budget can hold.
RefineReport refine_mesh(Mesh& mesh, Predicates& pred, const RefineOptions& opt);

// Whether opt's memory budget is still to be asked of the machine (probe_memory, no budget given).
inline bool asks_memory(const RefineOptions& opt) { return opt.probe_memory && !(opt.memory_budget > 0.0); }
// opt.memory_budget, asked of the machine now where asks_memory(opt).
double memory_budget_of(const RefineOptions& opt);

// Adds from's counts of work done (Steiner points, splits, refusals, stops) to to's; the closing
// survey's counts are not added (they describe one mesh).
void add_counts(RefineReport& to, const RefineReport& from);

}  // namespace deltri
