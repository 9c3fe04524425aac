#include "refine/refine_in_parts.h"

#include <algorithm>
#include <iterator>
#include <memory>
#include <utility>
#include <vector>

#include "geometry/box.h"
#include "mesh/operations.h"
#include "mesh/parts.h"
#include "refine/algorithm_corner_lopping.h"
#include "refine/criteria.h"
#include "refine/bottom_scale.h"
#include "refine/kept_boundary.h"
#include "refine/termination_guard.h"
#include "refine/terminator.h"
#include "util/big_allocator.h"
#include "util/run_both.h"

namespace deltri {
namespace {

// Which live triangles go to the second part: those whose centroids lie beyond the median of the
// centroids along the longer side of their bounding box, so that both parts start with as many
// triangles. Empty when one side would be nearly empty (many centroids on the median).
std::vector<std::uint8_t> cut_in_two(const Mesh& mesh) {
  Box box;
  for (TriangleId t{0}; t < mesh.triangle_slots(); ++t)
    if (mesh.is_live(t))
      for (unsigned i = 0; i < 3; ++i) box.add(mesh.point(mesh.corner[edge_of(t, i)]));
  const bool along_x = box.width() >= box.height();
  std::vector<double> key(mesh.triangle_slots(), 0.0);
  std::vector<double> keys;
  keys.reserve(mesh.live_triangles());
  for (TriangleId t{0}; t < mesh.triangle_slots(); ++t) {
    if (!mesh.is_live(t)) continue;
    for (unsigned i = 0; i < 3; ++i) {
      const Point& p = mesh.point(mesh.corner[edge_of(t, i)]);
      key[t] += along_x ? p.x : p.y;
    }
    keys.push_back(key[t]);
  }
  if (keys.empty()) return {};
  const auto middle = keys.begin() + static_cast<std::ptrdiff_t>(keys.size() / 2);
  std::nth_element(keys.begin(), middle, keys.end());
  const double median = *middle;
  std::vector<std::uint8_t> moves(mesh.triangle_slots(), 0);
  std::size_t left = 0;
  for (TriangleId t{0}; t < mesh.triangle_slots(); ++t)
    if (mesh.is_live(t)) left += (moves[t] = key[t] < median ? 0 : 1) == 0;
  if (4 * left < keys.size() || 4 * (keys.size() - left) < keys.size()) return {};
  return moves;
}

// A part's refinement, once its own parts and seams are done: what its Terminators counted, the
// triangles they left bad where their turn came (some may have been split or replaced since), and
// what the next Terminator goes on from.
struct PartResult {
  RefineReport report;
  std::vector<TriangleId> unsplit;
  TerminatorStart end;
};

// A part that is not cut again: its Terminator runs Fig. 38 to the end.
PartResult refine_whole_part(Mesh& mesh, Predicates& pred, const RefineOptions& opt, TerminatorStart start) {
  // What cutting and starting the part freed (keys, maps, the other side's copies) is held by the
  // malloc arenas as holes the growing Terminator cannot reuse: given back before it starts, it
  // is not under the peak, which sits at the end of the parts' refinement (50x50 holes, four
  // threads: about 6 MiB).
  release_free_heap();
  Terminator terminator(mesh, pred, opt, std::move(start));
  terminator.track_unsplit();
  terminator.refine_all();
  PartResult result{terminator.report(), std::move(terminator).unsplit_triangles(), {}};
  result.end = std::move(terminator).hand_over();  // unsplit_triangles took only its list
  result.report.parts = 1;
  return result;
}

// The whole mesh's start once the subsegments the initial mesh encroaches upon are split, on the
// whole mesh (Fig. 38 l.3-6): the long boundary segments of a fresh triangulation make long thin
// triangles, which would put long edges into the seam, and the parts could not refine near them.
TerminatorStart split_initial_encroachments(Mesh& mesh, Predicates& pred, const RefineOptions& opt,
                                            RefineReport& counts) {
  TerminatorStart start = TerminatorStart::of(mesh, opt);
  start.hopeless_edges = 0;  // parts_apply
  Terminator terminator(mesh, pred, opt, std::move(start));
  terminator.split_initial_encroachments();
  counts = terminator.report();
  return std::move(terminator).hand_over();
}

std::uint64_t steiner_of(const RefineReport& r) { return r.interior_steiner + r.segment_steiner; }

// The vertices a side of the cut needs besides those of its triangles (side 1: those that move,
// 0: those that stay): the ends of the segment pieces of its subsegments and of its refinement
// splits (shells and mirrored splits are measured from them), and the corners of its triangles,
// which cut_off and hold_only would add anyway.
std::vector<char> vertices_needed(const Mesh& mesh, const std::vector<std::uint8_t>& moves, const SegmentPieces& pieces,
                                  std::uint8_t side) {
  std::vector<char> keep(mesh.vertex_count(), 0);
  const auto keep_ends = [&](const PieceEnds& ends) {
    for (VertexId v : ends)
      if (v != kNone) keep[v] = 1;
  };
  for (TriangleId t{0}; t < mesh.triangle_slots(); ++t) {
    if (moves[t] != side || !mesh.is_live(t)) continue;
    for (unsigned i = 0; i < 3; ++i) {
      const EdgeRef e = edge_of(t, i);
      keep[mesh.corner[e]] = 1;
      mesh.subseg.fetch_ahead(e);
      if (mesh.subseg[e] < pieces.of_subsegment.size()) keep_ends(pieces.of_subsegment[mesh.subseg[e]]);
    }
  }
  // A split is never a piece's end, so keep[] marks a split only as a corner of the part.
  for (const SegmentPieces::Split& split : pieces.splits)
    if (keep[split.vertex]) keep_ends(split.piece);
  return keep;
}

// The start of a side of the cut in its ids (cut_off, hold_only: it holds `vertices` and `records`
// of the mesh's `count` vertices): the pieces, splits, apices and locks of what it holds, and the
// whole mesh's extent.
TerminatorStart start_of_part(const TerminatorStart& from, std::size_t count, const std::vector<VertexId>& vertices,
                              const std::vector<SubsegmentId>& records) {
  TerminatorStart start{from.guard_floor, from.proven_range, from.steiner_cap, from.cap_kind, {}, {}, {}, from.hopeless_edges,
                        from.small_pages, from.extent, from.memory_probe_slots};
  std::vector<VertexId> local(count, kNone);
  for (VertexId i{0}; i < vertices.size(); ++i) local[vertices[i]] = i;
  const auto local_ends = [&](const PieceEnds& p) {
    return PieceEnds{p[0] == kNone ? kNone : local[p[0]], p[1] == kNone ? kNone : local[p[1]]};
  };
  SegmentPieces& pieces = start.pieces;
  pieces.of_subsegment.reserve(records.size());
  for (SubsegmentId s : records) pieces.of_subsegment.push_back(local_ends(from.pieces.of_subsegment[s]));
  for (const SegmentPieces::Split& split : from.pieces.splits)
    if (local[split.vertex] != kNone) pieces.splits.push_back({local[split.vertex], local_ends(split.piece)});
  std::vector<std::uint64_t> keys;
  if (from.pieces.initial)
    for (std::uint64_t key : *from.pieces.initial) {
      const VertexId a = local[key >> 32], b = local[key & 0xffffffffu];
      if (a != kNone && b != kNone) keys.push_back(SegmentPieces::piece_key(a, b));
    }
  // Sorted already: the part's ids keep the order of the mesh's.
  pieces.initial = std::make_shared<const std::vector<std::uint64_t>>(std::move(keys));
  start.apices = from.apices.of_vertices(vertices);
  start.locked.reserve(records.size());
  for (SubsegmentId s : records) start.locked.push_back(s < from.locked.size() && from.locked[s]);
  return start;
}

// What the side that stays goes on from at the join, besides its own end: the parts of the mesh's
// start that are the same in the mesh's ids whatever the side did (the splits before the cut, the
// initial pieces, the apices, the locks of what it does not hold) and the pieces of the records
// neither side holds.
struct WholeStart {
  std::vector<SegmentPieces::Split> splits;
  SegmentApices apices;
  std::vector<char> locked;
  std::vector<PieceEnds> rest_pieces;  // by Held::rest_records
  // The initial pieces' keys that neither side holds both ends of, sorted; the sides' own lists
  // give the rest back at the join, so that the mesh's whole list is not kept while they refine.
  std::vector<std::uint64_t> rest_keys;
};

// The initial pieces' keys of the mesh at the cut (sorted), whose ends are held by neither side
// alone.
std::vector<std::uint64_t> keys_of_neither(const SegmentPieces& pieces, std::size_t count, const Held& held,
                                           const CutOff& cut) {
  std::vector<std::uint64_t> rest;
  if (!pieces.initial) return rest;
  std::vector<char> side(count, 0);  // bit 0: the side that stays holds it, bit 1: the part
  for (VertexId v : held.vertices) side[v] |= 1;
  for (VertexId v : cut.vertices) side[v] |= 2;
  for (std::uint64_t key : *pieces.initial)
    if ((side[key >> 32] & side[key & 0xffffffffu]) == 0) rest.push_back(key);
  return rest;
}

// The mesh's initial pieces' keys again: each side's in the mesh's ids (ids keep their order, so
// each list stays sorted) merged with those neither held.
std::shared_ptr<const std::vector<std::uint64_t>> whole_keys(const SegmentPieces& mine, const SegmentPieces& right,
                                                             const Held& held, const CutOff& cut,
                                                             std::vector<std::uint64_t> rest) {
  const auto mapped = [](const SegmentPieces& pieces, const auto& to_whole) {
    std::vector<std::uint64_t> keys;
    if (!pieces.initial) return keys;
    keys.reserve(pieces.initial->size());
    for (std::uint64_t key : *pieces.initial)
      keys.push_back(static_cast<std::uint64_t>(to_whole(VertexId{static_cast<std::uint32_t>(key >> 32)})) << 32 |
                     to_whole(VertexId{static_cast<std::uint32_t>(key & 0xffffffffu)}));
    return keys;
  };
  const std::vector<std::uint64_t> left_keys = mapped(mine, [&](VertexId v) { return held.whole_vertex(v); });
  const std::vector<std::uint64_t> right_keys = mapped(right, [&](VertexId v) { return cut.vertices[v]; });
  std::vector<std::uint64_t> sides;
  sides.reserve(left_keys.size() + right_keys.size());
  std::set_union(left_keys.begin(), left_keys.end(), right_keys.begin(), right_keys.end(), std::back_inserter(sides));
  std::vector<std::uint64_t> keys;
  keys.reserve(sides.size() + rest.size());
  std::merge(sides.begin(), sides.end(), rest.begin(), rest.end(), std::back_inserter(keys));
  return std::make_shared<const std::vector<std::uint64_t>>(std::move(keys));
}

// The end of the side that stayed in the mesh's ids (hold_all), as it would be had the side been
// refined with them: the pieces and locks of what it holds mapped back, those of the records only
// the part cut off holds from its end (a record's piece never changes), the rest from `whole`.
TerminatorStart whole_end(TerminatorStart local, WholeStart& whole, const Held& held, const CutOff& cut,
                          const TerminatorStart& right) {
  TerminatorStart end = std::move(local);
  const std::size_t n = held.vertices.size(), nr = held.records.size();
  const auto whole_ends = [&](const PieceEnds& p) { return PieceEnds{held.whole_vertex(p[0]), held.whole_vertex(p[1])}; };
  const auto cut_ends = [&](const PieceEnds& p) {
    return PieceEnds{p[0] == kNone ? kNone : cut.vertices[p[0]], p[1] == kNone ? kNone : cut.vertices[p[1]]};
  };
  std::vector<PieceEnds>& mine = end.pieces.of_subsegment;
  std::vector<PieceEnds> pieces(held.whole_records + (mine.size() > nr ? mine.size() - nr : 0), PieceEnds{kNone, kNone});
  for (std::size_t j = 0; j < cut.records.size() && j < right.pieces.of_subsegment.size(); ++j)
    pieces[cut.records[j]] = cut_ends(right.pieces.of_subsegment[j]);
  for (std::size_t j = 0; j < held.rest_records.size(); ++j) pieces[held.rest_records[j]] = whole.rest_pieces[j];
  for (SubsegmentId s{0}; s < mine.size(); ++s) pieces[held.whole_record(s)] = whole_ends(mine[s]);
  mine = std::move(pieces);
  std::vector<SegmentPieces::Split> splits = std::move(whole.splits);
  for (const SegmentPieces::Split& split : end.pieces.splits)
    if (split.vertex >= n) splits.push_back({held.whole_vertex(split.vertex), whole_ends(split.piece)});
  end.pieces.splits = std::move(splits);
  end.pieces.initial = whole_keys(end.pieces, right.pieces, held, cut, std::move(whole.rest_keys));
  end.apices = std::move(whole.apices);
  std::vector<char> locked = std::move(whole.locked);
  for (SubsegmentId s{0}; s < end.locked.size(); ++s) {
    const SubsegmentId w = held.whole_record(s);
    if (w >= locked.size()) locked.resize(w + 1, 0);
    locked[w] = end.locked[s];
  }
  end.locked = std::move(locked);
  return end;
}

// The seam's Terminator goes on from both sides' segment pieces and locks, in the joined ids;
// the seam's own records are as they were before the cut.
TerminatorStart join_starts(TerminatorStart left, const TerminatorStart& right, const std::vector<char>& before,
                            const Mesh& joined, const PartIds& ids, const CutOff& cut) {
  TerminatorStart start = std::move(left);
  SegmentPieces& pieces = start.pieces;
  const auto joined_ends = [&](const PieceEnds& p) { return PieceEnds{ids.vertex(p[0]), ids.vertex(p[1])}; };
  for (const SegmentPieces::Split& split : right.pieces.splits)
    if (split.vertex >= ids.v0) pieces.splits.push_back({ids.vertex(split.vertex), joined_ends(split.piece)});
  pieces.of_subsegment.resize(ids.record_base, {kNone, kNone});
  for (SubsegmentId s = ids.s0; s < right.pieces.of_subsegment.size(); ++s)
    pieces.of_subsegment.push_back(joined_ends(right.pieces.of_subsegment[s]));
  pieces.of_subsegment.resize(joined.subsegments.size(), {kNone, kNone});
  std::vector<char>& locked = start.locked;
  locked.resize(joined.subsegments.size(), 0);
  const auto locked_right = [&](SubsegmentId s) { return s < right.locked.size() && right.locked[s]; };
  for (SubsegmentId s{0}; s < ids.s0; ++s)
    if (cut.part_records[cut.records[s]]) locked[cut.records[s]] = locked_right(s);
  for (SubsegmentId s{0}; s < cut.cut_records.size(); ++s)
    if (cut.cut_records[s]) locked[s] = s < before.size() && before[s];
  const std::size_t right_records = joined.subsegments.size() - ids.record_base + ids.s0;  // its own count
  for (SubsegmentId s = ids.s0; s < right_records; ++s) locked[ids.record(s, kSeamEdge)] = locked_right(s);
  return start;
}

// Sews the seam and flips it Delaunay; returns what the seam's Terminator starts from: the
// triangles the sides left unsplit, those on the seam and those the flips made.
std::vector<TriangleId> sew_and_flip(Mesh& mesh, Predicates& pred, const PartIds& ids, const CutOff& cut,
                                     const std::vector<TriangleId>& left_unsplit,
                                     const std::vector<TriangleId>& right_unsplit, int threads) {
  const std::vector<EdgeRef> seam = sew_cut(mesh, cut, ids, kSeamEdge, threads);
  std::vector<TriangleId> seeds = left_unsplit;
  for (TriangleId t : right_unsplit) seeds.push_back(ids.triangle(t));
  for (EdgeRef e : seam) {
    seeds.push_back(triangle_of(e));
    seeds.push_back(triangle_of(mesh.link[e]));
  }
  flip_delaunay_from(mesh, pred, seam, seeds);
  std::sort(seeds.begin(), seeds.end());
  seeds.erase(std::unique(seeds.begin(), seeds.end()), seeds.end());
  return seeds;
}

// How a part is refined: its depth of cuts left, the threads it may use, and the options of the
// Terminators of its parts (one thread each) and of its seam (the caller's at the top).
struct PartPlan {
  int depth = 0;
  int threads = 1;
  const RefineOptions* parts = nullptr;
  const RefineOptions* seam = nullptr;
  std::uint64_t spent = 0;  // Steiner points already counted against the part's cap (the top's initial splits)
  bool survey = false;      // the top: the seam's Terminator ends with the closing survey
};

PartResult refine_part(Mesh& mesh, Predicates& pred, const PartPlan& plan, TerminatorStart start);

// Each side's start from the part's, and the keys of the initial pieces neither side holds; the
// two sides' at once when `parallel` (which also lowered the 45x45 holes' peak by 0.5 MiB).
void start_sides(const TerminatorStart& start, const Held& held, const CutOff& cut, bool parallel,
                 TerminatorStart& left, TerminatorStart& right, std::vector<std::uint64_t>& neither) {
  run_both(
      parallel, [&] { right = start_of_part(start, held.whole_vertices, cut.vertices, cut.records); },
      [&] {
        left = start_of_part(start, held.whole_vertices, held.vertices, held.records);
        neither = keys_of_neither(start.pieces, held.whole_vertices, held, cut);
      });
}

// Both sides of a cut, each with half the Steiner cap, the seam's records locked, and arrays that
// grow in small pages (several meshes' partly used last huge pages had cost 7 MB of the peak on
// the 45x45 holes, and no time that could be measured). With two threads or more the right side
// runs on a thread of its own and the threads are shared out; with one, the right side first:
// either way each side is refined exactly as it would be alone.
void refine_sides(Mesh& mesh, CutOff& cut, const Held& held, Predicates& pred, const PartPlan& plan,
                  TerminatorStart start, PartResult& left, PartResult& right) {
  start.steiner_cap /= 2;
  start.locked.resize(cut.cut_records.size(), 0);
  for (SubsegmentId s{0}; s < cut.cut_records.size(); ++s) start.locked[s] |= cut.cut_records[s];
  start.small_pages = true;
  TerminatorStart right_start, left_start;
  std::vector<std::uint64_t> neither;
  start_sides(start, held, cut, plan.threads >= 2, left_start, right_start, neither);
  WholeStart whole{std::move(start.pieces.splits), std::move(start.apices), std::move(start.locked), {},
                   std::move(neither)};
  for (SubsegmentId s : held.rest_records) whole.rest_pieces.push_back(start.pieces.of_subsegment[s]);
  start = TerminatorStart{};  // its whole-size arrays are not needed while the sides are refined
  PartPlan left_plan{plan.depth - 1, plan.threads - plan.threads / 2, plan.parts, plan.parts, 0, false};
  PartPlan right_plan = left_plan;
  right_plan.threads = std::max(1, plan.threads / 2);
  PredicateCounters right_counted;
  // A side's Terminator (its queue, its indices) is freed into the malloc arena of the thread that
  // ran it, which keeps it: the side refined next, or the other thread's, would hold it on top
  // (50x50 holes, two threads: 3 MiB of the peak, which sits in the last parts' refinement).
  // The right side counts its predicates on its own thread's stack, where no other thread writes.
  const auto refine_right = [&] {
    Predicates right_pred;
    right = refine_part(cut.part, right_pred, right_plan, std::move(right_start));
    right_counted = right_pred.counters;
    release_free_heap();
  };
  const auto refine_left = [&] {
    left = refine_part(mesh, pred, left_plan, std::move(left_start));
    release_free_heap();
  };
  run_both(plan.threads >= 2, refine_right, refine_left);
  pred.counters.add(right_counted);
  left.end = whole_end(std::move(left.end), whole, held, cut, right.end);
}

// Joins the sides, flips the seam Delaunay and refines around it; the part's counts are the seam
// Terminator's and the sides'.
PartResult join_sides(Mesh& mesh, Predicates& pred, const PartPlan& plan, CutOff& cut, PartResult& left,
                      PartResult& right, const TerminatorStart& before) {
  const std::uint64_t seam_edges = cut.cut_keys.size();
  const PartIds ids = append_part(mesh, cut, kSeamEdge, plan.threads);
  const std::vector<TriangleId> seeds = sew_and_flip(mesh, pred, ids, cut, left.unsplit, right.unsplit, plan.threads);
  TerminatorStart seam_start = join_starts(std::move(left.end), right.end, before.locked, mesh, ids, cut);
  // The right side's small arrays and its Terminator's queue were freed into the malloc arena of
  // the thread that refined it, which kept them: the seams and the rest of the run held them on
  // top (50x50 holes, one thread: 2.6 MiB of the peak).
  release_free_heap();
  const std::uint64_t used = plan.spent + steiner_of(left.report) + steiner_of(right.report);
  seam_start.steiner_cap = before.steiner_cap > used ? before.steiner_cap - used : 0;
  seam_start.cap_kind = before.cap_kind;
  Terminator seam_terminator(mesh, pred, *plan.seam, std::move(seam_start));
  seam_terminator.track_unsplit();
  seam_terminator.refine_around(seeds);
  PartResult joined;
  joined.report = plan.survey ? seam_terminator.finish() : seam_terminator.report();
  joined.unsplit = std::move(seam_terminator).unsplit_triangles();
  joined.end = std::move(seam_terminator).hand_over();
  RefineReport& report = joined.report;
  report.seam_steiner = steiner_of(report) + left.report.seam_steiner + right.report.seam_steiner;
  report.seam_seeds = seeds.size() + left.report.seam_seeds + right.report.seam_seeds;
  report.seam_edges = seam_edges + left.report.seam_edges + right.report.seam_edges;
  report.parts = left.report.parts + right.report.parts;
  report.peak_queue = std::max(report.peak_queue, left.report.peak_queue + right.report.peak_queue);
  for (const RefineReport* side : {&left.report, &right.report}) add_counts(report, *side);
  return joined;
}

// A part cut in two by `moves` (cut_in_two's): both sides refined, then joined.
PartResult refine_cut(Mesh& mesh, Predicates& pred, const PartPlan& plan, TerminatorStart start,
                      const std::vector<std::uint8_t>& moves) {
  TerminatorStart before;  // what the seam goes on from: the part's cap and locks
  before.steiner_cap = start.steiner_cap;
  before.cap_kind = start.cap_kind;
  before.locked = start.locked;
  std::vector<char> keep, needed;
  run_both(
      plan.threads >= 2, [&] { needed = vertices_needed(mesh, moves, start.pieces, 1); },
      [&] { keep = vertices_needed(mesh, moves, start.pieces, 0); });
  CutOff cut = cut_off(mesh, moves, kSeamEdge, std::move(needed));
  Held held = hold_only(mesh, cut, std::move(keep), plan.threads);
  PartResult left, right;
  refine_sides(mesh, cut, held, pred, plan, std::move(start), left, right);
  hold_all(mesh, held, cut, plan.threads);
  release_free_heap();
  return join_sides(mesh, pred, plan, cut, left, right, before);
}

PartResult refine_part(Mesh& mesh, Predicates& pred, const PartPlan& plan, TerminatorStart start) {
  const std::vector<std::uint8_t> moves = plan.depth > 0 ? cut_in_two(mesh) : std::vector<std::uint8_t>{};
  if (moves.empty()) return refine_whole_part(mesh, pred, *plan.parts, std::move(start));
  return refine_cut(mesh, pred, plan, std::move(start), moves);
}

}  // namespace

int part_depth(const Mesh& mesh, const RefineOptions& opt) {
  const std::uint64_t live = mesh.live_triangles();
  std::uint64_t least = std::max<std::uint64_t>(2, opt.part_min_triangles);
  int depth = 0;
  for (; depth < kMaxPartDepth && live >= least; least *= 8) ++depth;
  return depth;
}

bool parts_apply(const Mesh& mesh, const RefineOptions& opt) {
  if (!opt.in_parts || !mesh.has_subsegments()) return false;
  const bool bounded = opt.angle.asked() || opt.size.any();
  if (!bounded || opt.size_test || opt.max_steiner >= 0 || KeptBoundary(opt).active() || opt.conforming_delaunay ||
      opt.decline_cluster_splits || opt.queue_order != QueueOrder::ShortestEdge || CornerLopping(opt).active())
    return false;
  if (opt.angle.cascades()) return false;
  if (part_depth(mesh, opt) < 1) return false;
  return count_hopeless_edges(mesh, opt.angle.sin2(), opt.threads) == 0;
}

RefineReport refine_in_parts(Mesh& mesh, Predicates& pred, const RefineOptions& asked) {
  // The parts share out the whole mesh's cap before any of them refines: the budget is asked now.
  RefineOptions opt = asked;
  opt.memory_budget = memory_budget_of(asked);
  opt.probe_memory = false;
  RefineOptions one_thread = opt;
  one_thread.threads = 1;
  const int depth = part_depth(mesh, opt);
  RefineReport initial;
  TerminatorStart whole = split_initial_encroachments(mesh, pred, opt, initial);
  whole.extent = extent_of(mesh);  // the parts' scale: every vertex, the initial splits included
  const std::uint64_t cap = whole.steiner_cap;
  const PartPlan plan{depth, std::max(1, opt.threads), &one_thread, &opt, steiner_of(initial), true};
  const std::vector<std::uint8_t> moves = cut_in_two(mesh);
  if (moves.empty()) {  // nothing to cut: one Terminator on the whole mesh
    RefineReport report = Terminator(mesh, pred, opt, std::move(whole)).run();
    add_counts(report, initial);
    return report;
  }
  RefineReport report = refine_cut(mesh, pred, plan, std::move(whole), moves).report;
  report.in_parts = true;
  add_counts(report, initial);
  report.steiner_cap = cap;
  return report;
}

}  // namespace deltri
