#include "refine/halves.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>
#include <vector>

#include "geometry/box.h"
#include "mesh/operations.h"
#include "refine/bad_triangles.h"
#include "refine/bottom_scale.h"
#include "refine/termination_guard.h"
#include "refine/terminator.h"
#include "util/run_both.h"

namespace deltri {
namespace {

constexpr std::uint8_t kLeft = 0, kRight = 1, kDeadSlot = 2;

// Each triangle slot's side of the cut, a line across the longer side of the bounding box at the
// median of the live triangles' centroids along it, so that both halves start with as many
// triangles; empty when one side would be nearly empty (many centroids on the median).
std::vector<std::uint8_t> cut_in_two(const Mesh& mesh) {
  Box box;
  for (const Point& p : mesh.points)
    if (std::isfinite(p.x) && std::isfinite(p.y)) box.add(p);
  const bool along_x = box.width() >= box.height();
  std::vector<double> key(mesh.triangle_slots(), 0.0);
  std::vector<double> keys;
  keys.reserve(mesh.live_triangles());
  for (TriangleId t = 0; t < mesh.triangle_slots(); ++t) {
    if (!mesh.is_live(t)) continue;
    for (EdgeRef e = 3 * t; e < 3 * t + 3; ++e) {
      const Point& p = mesh.point(mesh.corner[e]);
      key[t] += along_x ? p.x : p.y;
    }
    keys.push_back(key[t]);
  }
  const auto middle = keys.begin() + static_cast<std::ptrdiff_t>(keys.size() / 2);
  std::nth_element(keys.begin(), middle, keys.end());
  const double median = *middle;
  std::vector<std::uint8_t> side(mesh.triangle_slots(), kDeadSlot);
  std::size_t left = 0;
  for (TriangleId t = 0; t < mesh.triangle_slots(); ++t)
    if (mesh.is_live(t)) left += (side[t] = key[t] < median ? kLeft : kRight) == kLeft;
  if (4 * left < keys.size() || 4 * (keys.size() - left) < keys.size()) return {};
  return side;
}

// What the cut leaves: the right half in a mesh of its own, which keeps every vertex and
// subsegment record of the whole so that their ids stay the same, and which records the right
// half owns (so that its splits of them are the ones kept) and which lie on the seam.
struct Cut {
  Mesh right;
  std::vector<char> right_records;
  std::vector<char> seam_records;
  std::uint64_t seam_edges = 0;
};

// Moves the right side's triangles into cut.right and marks the seam on both sides: seam edges
// without a subsegment get kSeamEdge, the others keep their record, which both halves lock.
Cut cut_off_right(Mesh& mesh, const std::vector<std::uint8_t>& side) {
  Cut cut;
  Mesh& r = cut.right;
  r = mesh.without_triangles();
  cut.right_records.assign(mesh.subsegments.size(), 0);
  cut.seam_records.assign(mesh.subsegments.size(), 0);
  std::vector<TriangleId> slot(mesh.triangle_slots(), kNone);
  TriangleId n = 0;
  for (TriangleId t = 0; t < mesh.triangle_slots(); ++t)
    if (side[t] == kRight) slot[t] = n++;
  r.corner.resize(3 * static_cast<std::size_t>(n));
  r.link.resize(r.corner.size());
  r.subseg.resize(r.corner.size());
  const std::size_t na = static_cast<std::size_t>(mesh.num_triangle_attributes);
  r.triangle_attributes.resize(n * na);
  if (!mesh.area_bound.empty()) r.area_bound.resize(n);
  for (TriangleId t = 0; t < mesh.triangle_slots(); ++t) {
    if (side[t] != kRight) continue;
    for (unsigned i = 0; i < 3; ++i) {
      const EdgeRef e = 3 * t + i, f = 3 * slot[t] + i;
      const EdgeRef twin = mesh.link[e];
      const bool seam = twin != kNone && side[triangle_of(twin)] == kLeft;
      r.corner[f] = mesh.corner[e];
      r.link[f] = twin == kNone || seam ? kNone : 3 * slot[triangle_of(twin)] + twin % 3;
      SubsegmentId s = mesh.subseg[e];
      cut.seam_edges += seam;
      if (s != kNone) (seam ? cut.seam_records : cut.right_records)[s] = 1;
      if (seam && s == kNone) mesh.subseg[twin] = s = kSeamEdge;
      r.subseg[f] = s;
    }
    std::copy_n(mesh.triangle_attributes.begin() + static_cast<std::ptrdiff_t>(t * na), na,
                r.triangle_attributes.begin() + static_cast<std::ptrdiff_t>(slot[t] * na));
    if (!mesh.area_bound.empty()) r.area_bound[slot[t]] = mesh.area_bound[t];
  }
  for (TriangleId t = 0; t < mesh.triangle_slots(); ++t)
    if (side[t] == kRight) mesh.kill_triangle(t);  // unlinks the left's seam edges
  return cut;
}

// Where the right half's ids land in the joined mesh: its vertices from v0 on and its records
// from s0 on (the ones refinement added) follow the left's, and its triangle slots follow the
// left's slots.
struct RightIds {
  VertexId v0, vertex_base;
  SubsegmentId s0, record_base;
  TriangleId triangle_base;
  VertexId vertex(VertexId v) const { return v == kNone || v < v0 ? v : vertex_base + (v - v0); }
  SubsegmentId record(SubsegmentId s) const {
    return s == kNone || s == kSeamEdge || s < s0 ? s : record_base + (s - s0);
  }
  EdgeRef edge(EdgeRef e) const { return e == kNone ? kNone : 3 * triangle_base + e; }
};

void append_records(Mesh& l, const Mesh& r, const RightIds& ids, const std::vector<char>& right_records) {
  const auto moved = [&](Subsegment s) {
    s.a = ids.vertex(s.a);
    s.b = ids.vertex(s.b);
    return s;
  };
  for (SubsegmentId s = 0; s < ids.s0; ++s)
    if (right_records[s]) l.subsegments[s] = moved(r.subsegments[s]);
  for (SubsegmentId s = ids.s0; s < r.subsegments.size(); ++s) l.subsegments.push_back(moved(r.subsegments[s]));
}

// The right half's triangles and vertices after the left's. The appends fault in fresh pages,
// most of their cost: the links and vertices on a second thread, the rest on this one.
void append_right(Mesh& l, Mesh& r, const RightIds& ids) {
  const auto links_and_vertices = [&] {
    move_appending(r.link, l.link, [&](EdgeRef e) { return ids.edge(e); });
    l.take_vertices(r, ids.v0);
  };
  const auto corners_and_subsegments = [&] {
    move_appending(r.corner, l.corner, [&](VertexId v) { return ids.vertex(v); });
    move_appending(r.subseg, l.subseg, [&](SubsegmentId s) { return ids.record(s); });
  };
  run_both(links_and_vertices, corners_and_subsegments);
  const auto& attributes = r.triangle_attributes;
  l.triangle_attributes.insert(l.triangle_attributes.end(), attributes.begin(), attributes.end());
  l.area_bound.insert(l.area_bound.end(), r.area_bound.begin(), r.area_bound.end());
  for (TriangleId t : r.free_triangles) l.free_triangles.push_back(ids.triangle_base + t);
}

// Bonds the seam edges of the two halves (each still a boundary edge on its side) and takes the
// seam marks off them; returns them, on the left side.
std::vector<EdgeRef> sew_seam(Mesh& mesh, const RightIds& ids, const std::vector<char>& seam_records) {
  struct Side {
    std::uint64_t key;
    EdgeRef edge;
    bool operator<(const Side& o) const { return key < o.key; }
  };
  std::vector<Side> left, right;
  for (EdgeRef e = 0; e < mesh.corner.size(); ++e) {
    if (mesh.link[e] != kNone || mesh.corner[e] == kNone) continue;
    const SubsegmentId s = mesh.subseg[e];
    if (s != kSeamEdge && (s >= seam_records.size() || !seam_records[s])) continue;
    const bool on_left = e < 3 * ids.triangle_base;
    // Keyed by the left's orientation of the edge.
    const VertexId a = on_left ? mesh.org(e) : mesh.dest(e), b = on_left ? mesh.dest(e) : mesh.org(e);
    (on_left ? left : right).push_back({static_cast<std::uint64_t>(a) << 32 | b, e});
  }
  std::sort(left.begin(), left.end());
  std::sort(right.begin(), right.end());
  if (left.size() != right.size()) throw std::logic_error("the halves' seams do not match");
  std::vector<EdgeRef> seam;
  seam.reserve(left.size());
  for (std::size_t k = 0; k < left.size(); ++k) {
    if (left[k].key != right[k].key) throw std::logic_error("the halves' seams do not match");
    const EdgeRef e = left[k].edge, f = right[k].edge;
    mesh.bond(e, f);
    if (mesh.subseg[e] == kSeamEdge) mesh.subseg[e] = mesh.subseg[f] = kNone;
    seam.push_back(e);
  }
  return seam;
}

// Lawson's flips from the seam edges until every edge is locally Delaunay. Each half is
// constrained Delaunay, so only the seam edges, and the sides of the quadrilaterals flipped, can
// fail the test. The triangles the flips make go to `touched`.
void flip_seam(Mesh& mesh, Predicates& pred, std::vector<EdgeRef> stack, std::vector<TriangleId>& touched) {
  while (!stack.empty()) {
    const EdgeRef e = stack.back();
    stack.pop_back();
    const EdgeRef twin = mesh.link[e];
    if (twin == kNone || mesh.subseg[e] != kNone) continue;
    if (pred.incircle(mesh.point(mesh.org(e)), mesh.point(mesh.dest(e)), mesh.point(mesh.apex(e)),
                      mesh.point(mesh.apex(twin))) <= 0)
      continue;
    const EdgeRef g = flip(mesh, e);  // a quadrilateral with a non-Delaunay diagonal is convex
    const EdgeRef h = mesh.link[g];
    touched.push_back(triangle_of(g));
    touched.push_back(triangle_of(h));
    for (EdgeRef x : {lnext(g), lprev(g), lnext(h), lprev(h)}) stack.push_back(x);
  }
}

// The seam's Terminator goes on from both halves' segment pieces and locks, in the joined ids;
// the seam's own records are free again.
TerminatorStart join_starts(TerminatorStart left, const TerminatorStart& right, const std::vector<char>& whole_locked,
                            const Mesh& joined, const RightIds& ids, const Cut& cut) {
  TerminatorStart start = std::move(left);
  SegmentPieces& pieces = start.pieces;
  for (const SegmentPieces::Split& split : right.pieces.splits)
    if (split.vertex >= ids.v0) pieces.splits.push_back({ids.vertex(split.vertex), split.piece});
  pieces.of_subsegment.resize(ids.record_base, {kNone, kNone});
  for (SubsegmentId s = ids.s0; s < right.pieces.of_subsegment.size(); ++s)
    pieces.of_subsegment.push_back(right.pieces.of_subsegment[s]);
  pieces.of_subsegment.resize(joined.subsegments.size(), {kNone, kNone});
  std::vector<char>& locked = start.locked;
  locked.resize(joined.subsegments.size(), 0);
  const auto locked_right = [&](SubsegmentId s) { return s < right.locked.size() && right.locked[s]; };
  for (SubsegmentId s = 0; s < ids.s0; ++s) {
    if (cut.right_records[s]) locked[s] = locked_right(s);
    if (cut.seam_records[s]) locked[s] = s < whole_locked.size() && whole_locked[s];
  }
  const std::size_t right_records = joined.subsegments.size() - ids.record_base + ids.s0;  // its own count
  for (SubsegmentId s = ids.s0; s < right_records; ++s) locked[ids.record(s)] = locked_right(s);
  return start;
}

// One half's refinement: its Terminator runs Fig. 38 to the end, and leaves what the seam's
// Terminator needs from it.
struct HalfResult {
  RefineReport report;
  std::vector<TriangleId> unsplit;  // Terminator::unsplit_triangles
  TerminatorStart end;
};

HalfResult refine_half(Mesh& mesh, Predicates& pred, const RefineOptions& opt, TerminatorStart start) {
  Terminator terminator(mesh, pred, opt, std::move(start));
  terminator.track_unsplit();
  terminator.refine_all();
  HalfResult result{terminator.report(), std::move(terminator).unsplit_triangles(), {}};
  result.end = std::move(terminator).hand_over();  // unsplit_triangles took only its list
  return result;
}

// The whole mesh's start once the subsegments the initial mesh encroaches upon are split, on the
// whole mesh (Fig. 38 l.3-6): the long boundary segments of a fresh triangulation make long thin
// triangles, which would put long edges into the seam, and the halves could not refine near them.
TerminatorStart split_initial_encroachments(Mesh& mesh, Predicates& pred, const RefineOptions& opt,
                                            RefineReport& counts) {
  TerminatorStart start = TerminatorStart::of(mesh, opt);
  start.hopeless_edges = 0;  // halves_apply
  Terminator terminator(mesh, pred, opt, std::move(start));
  terminator.split_initial_encroachments();
  counts = terminator.report();
  return std::move(terminator).hand_over();
}

// Both halves at once, the right on a thread of its own. Each gets half the Steiner cap, locks
// the subsegments on the seam, and grows in small pages: two meshes' partly used last huge pages
// had cost 7 MB of the peak (the 45x45 holes), and no time that could be measured.
void refine_both(Mesh& mesh, Cut& cut, Predicates& pred, const RefineOptions& one_thread, TerminatorStart whole,
                 HalfResult& left, HalfResult& right, bool at_once) {
  whole.steiner_cap /= 2;
  whole.locked.resize(cut.seam_records.size(), 0);
  for (SubsegmentId s = 0; s < cut.seam_records.size(); ++s) whole.locked[s] |= cut.seam_records[s];
  whole.small_pages = true;
  TerminatorStart left_start = whole;
  Predicates right_pred;
  const auto refine_right = [&] { right = refine_half(cut.right, right_pred, one_thread, std::move(whole)); };
  const auto refine_left = [&] { left = refine_half(mesh, pred, one_thread, std::move(left_start)); };
  if (at_once) {
    run_both(refine_right, refine_left);
  } else {  // the same two refinements, one after the other: the same halves
    refine_right();
    refine_left();
  }
  pred.counters.add(right_pred.counters);
}

// Sews the seam and flips it Delaunay; returns what the seam's Terminator starts from: the
// triangles the halves left unsplit, those on the seam and those the flips made.
std::vector<TriangleId> sew_and_flip(Mesh& mesh, Predicates& pred, const RightIds& ids, const Cut& cut,
                                     const std::vector<TriangleId>& left_unsplit,
                                     const std::vector<TriangleId>& right_unsplit) {
  const std::vector<EdgeRef> seam = sew_seam(mesh, ids, cut.seam_records);
  std::vector<TriangleId> seeds = left_unsplit;
  for (TriangleId t : right_unsplit) seeds.push_back(ids.triangle_base + t);
  for (EdgeRef e : seam) {
    seeds.push_back(triangle_of(e));
    seeds.push_back(triangle_of(mesh.link[e]));
  }
  flip_seam(mesh, pred, seam, seeds);
  std::sort(seeds.begin(), seeds.end());
  seeds.erase(std::unique(seeds.begin(), seeds.end()), seeds.end());
  return seeds;
}

}  // namespace

bool halves_apply(const Mesh& mesh, const RefineOptions& opt) {
  if (!opt.in_halves || !mesh.has_subsegments()) return false;
  const bool bounded = opt.angle.asked() || opt.size.any();
  if (!bounded || opt.size_test || opt.max_steiner >= 0 || opt.no_steiner_on_segments != 0 || opt.conforming_delaunay ||
      opt.decline_cluster_splits || opt.queue_order != QueueOrder::Ratio)
    return false;
  if (opt.angle.cascades()) return false;
  if (mesh.live_triangles() < kHalvesMinTriangles) return false;
  return count_hopeless_edges(mesh, opt.angle.sin2()) == 0;
}

RefineReport refine_in_halves(Mesh& mesh, Predicates& pred, const RefineOptions& opt) {
  RefineOptions one_thread = opt;
  one_thread.threads = 1;
  RefineReport initial;
  TerminatorStart whole = split_initial_encroachments(mesh, pred, opt, initial);
  const std::vector<std::uint8_t> side = cut_in_two(mesh);
  if (side.empty()) {
    RefineReport report = Terminator(mesh, pred, opt, std::move(whole)).run();
    add_counts(report, initial);
    return report;
  }
  const VertexId v0 = mesh.vertex_count();
  const SubsegmentId s0 = static_cast<SubsegmentId>(mesh.subsegments.size());
  Cut cut = cut_off_right(mesh, side);
  const std::uint64_t cap = whole.steiner_cap;
  const CapKind cap_kind = whole.cap_kind;
  const std::vector<char> whole_locked = whole.locked;
  HalfResult left, right;
  refine_both(mesh, cut, pred, one_thread, std::move(whole), left, right, opt.threads >= 2);

  const RightIds ids{v0, mesh.vertex_count(), s0, static_cast<SubsegmentId>(mesh.subsegments.size()),
                     mesh.triangle_slots()};
  append_records(mesh, cut.right, ids, cut.right_records);
  append_right(mesh, cut.right, ids);
  cut.right = Mesh{};
  const std::vector<TriangleId> seeds = sew_and_flip(mesh, pred, ids, cut, left.unsplit, right.unsplit);

  TerminatorStart seam_start = join_starts(std::move(left.end), right.end, whole_locked, mesh, ids, cut);
  const std::uint64_t used = initial.segment_steiner + left.report.interior_steiner + left.report.segment_steiner +
                             right.report.interior_steiner + right.report.segment_steiner;
  seam_start.steiner_cap = cap > used ? cap - used : 0;
  seam_start.cap_kind = cap_kind;
  Terminator seam_terminator(mesh, pred, opt, std::move(seam_start));
  seam_terminator.refine_around(seeds);
  RefineReport report = seam_terminator.finish();
  report.in_halves = true;
  report.seam_steiner = report.interior_steiner + report.segment_steiner;
  report.seam_seeds = seeds.size();
  report.seam_edges = cut.seam_edges;
  for (const RefineReport* part : {&left.report, &right.report, &initial}) add_counts(report, *part);
  report.steiner_cap = cap;
  report.peak_queue = std::max(report.peak_queue, left.report.peak_queue + right.report.peak_queue);
  return report;
}

}  // namespace deltri
