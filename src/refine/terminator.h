// The Terminator of Shewchuk 2001, Appendix A. Its core, terminator_core.cpp, reads like Figures 38
// and 39: refine_all() and split_bad_triangle() are DELAUNAYTERMINATOR, split_encroached_subsegments()
// and split_subsegment() SPLITENCROACHEDSUBSEGMENTS, new_vertex() NEWVERTEX, and each bad triangle
// or encroached subsegment served gets an Outcome (outcome.h). The policies the core asks (where a
// point goes, when the guard refuses) are in terminator_policies.cpp, Chew's step in chew_step.cpp;
// terminator.cpp is the driver around the core (set-up, the queue's mechanics, prefetching and page
// warming, bookkeeping), terminator_survey.cpp the closing survey. Which algorithm runs (with
// Sec. 7.2's interior bound and the cluster-split refusal), -Y/-YY, corner-lopping and the bottom
// of double precision are policy objects chosen at construction (policy_, kept_, mending_,
// lopping_, bottom_); the methods read their values and never the switches (docs/refinement.md,
// "The policies").
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "geometry/box.h"
#include "geometry/predicates.h"
#include "mesh/mesh.h"
#include "refine/algorithm_corner_lopping.h"
#include "refine/algorithm_policy.h"
#include "refine/bottom_scale.h"
#include "refine/criteria.h"
#include "refine/kept_boundary.h"
#include "refine/mending.h"
#include "refine/candidate_probe.h"
#include "refine/clusters.h"
#include "refine/edge_finder.h"
#include "refine/encroached.h"
#include "refine/encroached_queue.h"
#include "refine/relocation.h"
#include "refine/mirrored_split.h"
#include "refine/outcome.h"
#include "refine/quality_queue.h"
#include "util/progress.h"
#include "refine/refine.h"
#include "refine/steiner_point.h"
#include "util/page_warmer.h"
#include "util/prefetch.h"

namespace deltri {

// The subsegment id of a seam edge (refine/refine_in_parts.h): an edge that refinement treats as a
// subsegment it may neither split nor cross, and which has no subsegment record.
inline constexpr SubsegmentId kSeamEdge{0xFFFFFFFEu};  // just below kNone

// What a Terminator takes from the initial mesh: the guard's edge floor and Steiner cap, the
// segment pieces, and the subsegments to leave whole. of() derives them; refine/refine_in_parts.cpp computes
// them once on the whole mesh, hands them to the Terminators of its two halves, and hands theirs
// on to the one that refines the seam.
struct TerminatorStart {
  // The guard's edge floor from the input's features; within the proven range it refuses nothing
  // and only tells whether the bottom of double precision is within reach.
  double guard_floor = 0.0;
  bool proven_range = false;  // within_proven_range (termination_guard.h): no floor, no Steiner cap
  std::uint64_t steiner_cap = 0;
  CapKind cap_kind = CapKind::Work;
  SegmentPieces pieces;
  SegmentApices apices;
  std::vector<char> locked;  // by subsegment record
  // The initial edges no double can give a good triangle (report.hopeless_edges), or -1 to count
  // them on the mesh when the bottom scale is within reach.
  std::int64_t hopeless_edges = -1;
  // Keep the arrays' growth in small pages (prefer_small_pages): for two meshes refined at once,
  // whose partly used last huge pages would add to the peak memory.
  bool small_pages = false;
  // Vertices the mesh does not hold whose box still counts (a part holds only its own vertices,
  // and its Terminator's scale is that of the whole mesh's): the extent is the box around both.
  // hand_over() gives the Terminator's extent, which a seam's Terminator extends by the joined mesh.
  Box extent;
  // The memory budget still to be asked (RefineOptions::probe_memory, kProbeAfterSteiner): the
  // triangle slots of the mesh the cap is measured beside; nothing when it is in steiner_cap.
  std::optional<std::uint64_t> memory_probe_slots;
  static TerminatorStart of(const Mesh& mesh, const RefineOptions& opt);
  static constexpr std::uint32_t kParallelStartSlots = 50000;
};

// The bounding box of the mesh's vertices (those with finite coordinates): a Terminator's scale.
Box extent_of(const Mesh& mesh);

class Terminator {
 public:
  Terminator(Mesh& mesh, Predicates& pred, const RefineOptions& opt);
  Terminator(Mesh& mesh, Predicates& pred, const RefineOptions& opt, TerminatorStart start);
  RefineReport run();  // refine_all, then finish

  // Fig. 38 l.3-10 on the whole mesh: split_initial_encroachments (l.3-6), then the bad triangles.
  void refine_all();
  void split_initial_encroachments();
  // Fig. 38 l.3-10 with Q_s and Q_t filled from `triangles` and their subsegments only: the rest of
  // the mesh is known to meet the bounds (refine/refine_in_parts.cpp).
  void refine_around(std::span<const TriangleId> triangles);
  // The closing survey of the triangles still bad.
  RefineReport finish();
  // The counts so far, without the closing survey.
  const RefineReport& report() const { return report_; }
  // With track_unsplit(), before refining: the triangles whose turn came and which were left as
  // they were (some may have been split or replaced since).
  void track_unsplit() { track_unsplit_ = true; }
  std::vector<TriangleId> unsplit_triangles() &&;
  // The segment pieces and locked subsegments so far, for a Terminator that goes on from here.
  TerminatorStart hand_over() &&;

 private:
  // The -Y / -YY and bottom-scale policies ask the mesh, the cavity and the probes.
  friend class KeptBoundary;
  friend class Mending;
  friend class BottomScale;

  // --- the core (terminator_core.cpp) ---
  // Fig. 38 l.12-25: one triangle from Q_t.
  Outcome split_bad_triangle(const QueuedTriangle& entry);
  struct Candidate {
    Point point;
    bool no_better_double = false;  // at the bottom scale, no double near it improves the mesh
  };
  Outcome insert_point(TriangleId t, const Assessment& a, const Candidate& c, const Probe& probe);  // l.15-17
  Outcome insert_free_vertex(const Point& p, const Probe& probe);  // l.16-17, no refusals
  Outcome split_encroached_instead(const QueuedTriangle& entry, const Assessment& a, const Probe& probe);  // l.18-25
  // Fig. 39 l.36-38; returns the number of subsegments split. owed_to_size: the splits are asked
  // for by a triangle over its size bound, and meet only the precision floor (floor_for).
  std::uint64_t split_encroached_subsegments(bool queue_triangles, bool owed_to_size = false);
  Outcome split_subsegment(EdgeRef s, bool queue_triangles, bool owed_to_size);  // Fig. 39 l.39-49
  void new_vertex(EdgeRef out, bool queue_triangles);  // Fig. 39 l.50-55; `out` leaves the new vertex

  // --- the policies (terminator_policies.cpp): a point, or a refusal ---
  std::optional<Outcome> choose_point(TriangleId t, const Assessment& a, Candidate& c);  // l.13
  std::optional<Outcome> guard_insertion(const Assessment& a, const Candidate& c, double radius) const;
  struct SplitRadius {
    double now, after_chew;  // the shortest edge a split at p would make, before and after Chew's step
    VertexId nearest = kNone;  // the vertex after_chew is measured to, when Chew's step is planned
  };
  struct SplitPlan {
    Point point;
    double floor = 0.0;  // the guard's floor for the split
    SplitRadius radius{};
    bool exactly_on = false;  // on the subsegment exactly (restore_delaunay_around)
  };
  std::optional<Outcome> plan_split(EdgeRef s, bool owed_to_size, SplitPlan& plan);  // Fig. 39 l.39
  Point split_point(EdgeRef s);  // l.39: the split-point policy plan_split consults
  std::optional<Outcome> replan_after_deletions(EdgeRef s, SplitPlan& plan);
  SplitRadius split_radius(EdgeRef s, const Point& p);
  bool split_radius_read() const;  // beyond plan_split's comparison with the floor
  bool split_clear_of(EdgeRef s, const Point& p, double floor) const;  // surely, without the search
  bool split_radius_at_least(EdgeRef s, const Point& p, double floor) const;
  // Would splitting s at p leave every new triangle counter-clockwise?
  // chew_pending: free vertices in s's diametral circle do not count (Chew's step deletes them).
  bool split_keeps_orientation(EdgeRef s, const Point& p, bool chew_pending);
  bool split_allowed(EdgeRef s, const Assessment& a, double d) const;  // Fig. 38 l.21
  // Ruppert, Chew: Sec. 6.2's sure-fire rule on the split of s planned as `plan`.
  bool refused_by_sure_fire_rule(EdgeRef s, const SplitPlan& plan) const;
  bool meets_at_small_angle(const PieceEnds& piece, VertexId w) const;
  bool parent_is_input_feature(const PieceEnds& piece) const;
  std::array<VertexId, 2> sure_fire_ancestors(EdgeRef shortest) const;
  bool budget_left();                   // the Steiner cap and -S
  void ask_memory_budget();  // the cap clamped to it, as TerminatorStart::of would have
  void set_cap(std::uint64_t cap, CapKind kind);
  bool move_corners(TriangleId t, StarGoal goal);  // relocation.h: true when a corner of t moved
  bool relocate_corners(TriangleId t);  // move_corners in the second stage of locally optimal points
  void open_obtuse_corner(TriangleId t, const Assessment& a);  // after a guard refusal (relocation.h)
  Outcome refused_for(TriangleId t, const Assessment& a, Outcome refusal);  // the same for a refused point
  double floor_at(const Point& p) const;  // the guard's edge floor where p lies
  double floor_for(const Assessment& a, const Point& p) const;  // the floor for splitting that triangle
  // assess_triangle plus the equal-shell exemption (shell_exempt), under t's bound (rules_for);
  // assess_with under the given rules (the closing survey: the -q bound).
  Assessment assess(TriangleId t) const { return assess_with(t, rules_for(t)); }
  Assessment assess_with(TriangleId t, const Criteria& rules) const { return assess_with(t, rules, side_measures(mesh_, t)); }
  Assessment assess_with(TriangleId t, const Criteria& rules, const SideMeasures& m) const;  // m: t's
  // Sec. 7.2: the 30 degrees, or -q. Inline for the common case (no interior bound): it is asked
  // for every triangle assessed.
  const Criteria& rules_for(TriangleId t) const {
    return policy_.interior_strategy == 0 ? rules_ : interior_rules_for(t);
  }
  const Criteria& interior_rules_for(TriangleId t) const;  // rules_for under an interior strategy
  bool below_asked_bound(const Assessment& a) const;   // under -q, not only under Sec. 7.2's bound
  bool only_for_interior_bound(TriangleId t, const Assessment& a) const;  // bad for Sec. 7.2's bound alone
  bool shell_exempt(EdgeRef shortest) const;
  // Only segment splits have pieces, and with -r the straight vertices of the earlier run's
  // segments (input vertices now, RefineOptions::straight_chains); the kinds, a byte per vertex,
  // stay in cache where the pieces would be a miss.
  bool may_lie_on_piece(VertexId v) const {
    return mesh_.kind[v] == VertexKind::Segment || (opt_.straight_chains && mesh_.kind[v] == VertexKind::Input);
  }
  bool stall_check_passed(std::uint64_t used);
  // The subsegment to split of a spared triangle beyond a corner whose angle is below the corner's
  // (kNone for any other), and that split, served in place of the triangle's point.
  EdgeRef beyond_corner_subsegment(EdgeRef shortest) const;
  Outcome split_beyond_corner(EdgeRef s);

  // --- Chew's step (chew_step.cpp), Fig. 39 l.40-43 ---
  // Returns the edge of the subsegment afterwards, or kNone.
  EdgeRef delete_free_vertices_near(EdgeRef s, const Point& p, bool queue_triangles);
  std::vector<VertexId> free_vertices_seen_from(EdgeRef s, const Point& p);
  bool too_close_to_split(VertexId w, const Point& p);
  static constexpr std::size_t kDeletionSearchLimit = 512;  // triangles looked at per split

  // --- the driver and bookkeeping (terminator.cpp) ---
  // Leaves s whole from now on, as -Y leaves the boundary: doubles cannot split it.
  void lock(EdgeRef s);
  // -D: tries the locked subsegments that are encroached again, in rounds while some split.
  void retry_locked_encroachments();
  static constexpr int kLockRetryRounds = 8;
  std::vector<EdgeRef> initially_encroached();  // Fig. 38 l.3-4
  // Fig. 38 l.10-11: serve Q_t until it is empty.
  void drain_queue();
  void publish_progress();  // to opt_.progress, if the caller asked for one
  void prefetch_queued() const;
  static constexpr std::size_t kPrefetchDistance = 8;  // queue entries ahead
  // Below this many triangle slots the arrays a pop reads (corners, links, points: about 32 bytes
  // a slot) take at most half of a 1 MiB L2 cache, and prefetching is only its own cost (about 200
  // instructions a pop, 4% of a small file's refinement).
  static constexpr std::uint32_t kPrefetchFromSlots = 1u << 14;
  // Tells the page warmer how far the mesh arrays are used (every kWarmInterval pops).
  void warm_pages();
  static constexpr unsigned kWarmInterval = 256;
  void enqueue_if_bad(TriangleId t);
  bool cannot_be_exempt(TriangleId t, const SideMeasures& m) const;  // from any of assess_with's exemptions
  void enqueue_subsegment(EdgeRef e);
  EdgeRef current_edge(const EncroachedSubsegment& entry);
  bool is_splittable(EdgeRef e) const;  // not kept by -Y / -YY, not a spoke, not a seam edge, not locked
  VertexId add_free_vertex(const Point& p, EdgeRef container);
  VertexId add_segment_vertex(const Point& p, EdgeRef s);
  Point centroid_of(TriangleId t) const;
  void drop_last_vertex();
  void survey_remaining();
  void survey(TriangleId from, TriangleId to, RefineReport& into) const;
  static constexpr std::uint32_t kParallelSurveySlots = 100000;
  static constexpr std::uint32_t kSurveyPrefetch = 16;

  Mesh& mesh_;
  Predicates& pred_;
  const RefineOptions opt_;
  // The algorithm's rules (algorithm_policy.h), chosen once: the methods read them, never which
  // algorithm it is, nor --interior-bound or --decline-cluster-splits.
  const AlgorithmPolicy policy_;
  Criteria rules_;
  Criteria interior_rules_;  // Sec. 7.2 (policy_.interior_strategy): rules_ with max(-q, 30 degrees)
  // Both rules let surely_good answer first (has_quick_verdict): enqueue_if_bad and the closing
  // survey skip the full assessment of a triangle it finds good.
  bool quick_verdict_ = false;
  CornerLopping lopping_;  // --corner-lopping
  KeptBoundary kept_;      // -Y / -YY
  Mending mending_;        // -Y / -YY, once Q_t is empty
  bool optimal_points_ = false;     // locally optimal Steiner points (--steiner=optimal; steiner_point.h)
  PetalSearch petal_;               // their search's scratch
  Relocator relocator_;             // free vertices moved above 34 degrees (relocation.h)
  std::uint64_t relocations_ = 0;
  double guard_floor_ = 0.0;           // the guard's edge floor from the input's features
  bool proven_range_ = false;          // the paper's theorems cover the run
  // The floor applied: guard_floor_, or 0 within the proven range, whose proofs are for circumcentres
  // and off-centres (locally optimal points keep the floor).
  double edge_floor_ = 0.0;
  std::uint64_t steiner_cap_ = 0;      // the guard's last line (termination_guard.h)
  CapKind cap_kind_ = CapKind::Work;
  std::optional<std::uint64_t> memory_probe_slots_;  // TerminatorStart::memory_probe_slots
  // --max-angle beyond what -q implies (no theorem ends it): at each doubling of the Steiner points
  // from kStallCheckFrom, the queue of bad triangles must have shrunk since the last (budget_left).
  static constexpr std::uint64_t kStallCheckFrom = 1u << 16;
  bool checks_stall_ = false;
  std::uint64_t next_stall_check_ = 0;
  std::size_t queued_at_last_check_ = SIZE_MAX;
  SegmentPieces pieces_;  // the piece of each subsegment and refinement split
  SegmentApices apices_;
  EdgeFinder finder_;
  Box extent_;  // the bounding box of the vertices: the queue's scale, the bottom scale's coordinates
  BottomScale bottom_;  // the bottom of double precision (bottom_scale.h)
  CavityMarks marks_;
  QualityQueue bad_triangles_;       // Q_t
  EncroachedQueue encroached_;       // Q_s
  RefineReport report_;
  ProgressShare progress_share_;  // this Terminator's part of opt_.progress
  std::vector<char> locked_;  // by subsegment record: a split failed for want of precision
  // Whether the mesh carries a cut's marks (kSeamEdge). They are set before a Terminator starts
  // and stay as they are while it runs; without them and without locks, is_splittable needs no
  // subsegment id, whose lookup missed the cache on every call where every triangle has a
  // subsegment (a thin strip).
  bool seams_ = true;
  // Whether the mesh may hold a free vertex (VertexKind::Free), the only kind Chew's step deletes:
  // without one, the step's search around every subsegment split finds nothing (a thin strip,
  // whose every vertex is on its boundary, spent a tenth of its instructions there). Looked for
  // where a refinement starts (look_for_free_vertices) and set by add_free_vertex. Without one the
  // split's plan also stands as made: its radius after the step is its radius now, and its
  // orientation check ignored no free apex, so replan_after_deletions is not needed.
  bool free_vertices_ = true;
  void look_for_free_vertices();
  void prefetch_new_subsegment_homes() const;
  // Ruppert, Chew: by vertex id, the insertion radius of each refinement split this Terminator
  // made, 0 for every other vertex (refused_by_sure_fire_rule).
  std::vector<double> split_radius_;
  // While the subsegments a rejected circumcentre encroaches upon are split: the ends of its
  // triangle's shortest edge that count as the splits' ancestors (sure_fire_ancestors), else kNone.
  std::array<VertexId, 2> sure_fire_parents_{kNone, kNone};
  bool track_unsplit_ = false;
  bool small_pages_ = false;
  std::vector<TriangleId> unsplit_;
  PageWarmer warmer_;  // last: its thread stops first
};

}  // namespace deltri
