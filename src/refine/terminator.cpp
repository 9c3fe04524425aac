#include "refine/terminator.h"

#include <algorithm>
#include <cmath>
#include <new>
#include <optional>
#include <utility>

#include "geometry/box.h"
#include "geometry/constructions.h"
#include "geometry/lattice.h"
#include "refine/algorithm_corner_lopping.h"
#include "refine/algorithm_policy.h"
#include "refine/criteria.h"
#include "refine/kept_boundary.h"
#include "refine/mending.h"
#include "mesh/operations.h"
#include "refine/bottom_scale.h"
#include "refine/split_permitted.h"
#include "refine/steiner_point.h"
#include "refine/termination_guard.h"
#include "util/invariant.h"
#include "util/run_both.h"

namespace deltri {
namespace {

// The edge length the size bounds ask for: sqrt of the smallest area bound, or the edge bound.
double size_floor_of(const Mesh& mesh, const RefineOptions& opt) {
  double smallest = opt.size.max_area > 0.0 ? opt.size.max_area : HUGE_VAL;
  if (opt.size.triangle_bounds)
    for (TriangleId t{0}; t < mesh.area_bound.size(); ++t)
      if (mesh.is_live(t) && mesh.area_bound[t] > 0.0) smallest = std::min(smallest, mesh.area_bound[t]);
  double floor = std::sqrt(smallest);
  if (opt.size.max_edge_length > 0.0) floor = std::min(floor, opt.size.max_edge_length);
  return std::isfinite(floor) ? floor : 0.0;
}

// The guard's edge floor from the input's features, one value for the whole run (floor_at adds the
// local precision floor): the smallest initial feature estimate scaled down, not an estimate at
// each new vertex: the Lipschitz extension f(u) + |uc| is an upper bound on lfs that grows without limit away from input
// vertices (halfway along a strip 1000 wide and 200000 long it reads 50000), so a floor taken from
// it refused ordinary insertions that real lfs allows. Any positive floor keeps termination
// certain; the global one never bites where the Terminator would have stopped anyway.
double guard_floor_of(const Mesh& mesh, const RefineOptions& opt, double input_angle,
                      const std::vector<double>& features) {
  const double smallest = features.empty() ? 0.0 : *std::min_element(features.begin(), features.end());
  // Beyond the practical range the floor is what stops cascades, so it stays unscaled there.
  const double scale = opt.angle.cascades() ? 1.0 : angle_scale(input_angle);
  return guard_floor(smallest * scale, size_floor_of(mesh, opt));
}

// The box around the vertices and `known` (TerminatorStart::extent).
Box extent_with(const Mesh& mesh, const Box& known) {
  Box box = extent_of(mesh);
  box.merge(known);
  return box;
}

// The squared diagonal of a box, 1 for an empty one.
double squared_diameter(const Box& box) {
  if (box.empty()) return 1.0;
  return box.width() * box.width() + box.height() * box.height();
}

// Size-bounded refinement ends with about twice as many triangles as its bounds ask for (the unit
// square at -a: 1.68 times); quality alone multiplies the triangles of a fresh constrained
// triangulation by a few (the 45x45 holes: 5.6 times), a run on an already refined mesh by about
// one. Reserving that up front spares the arrays' doublings, each of which copies everything and
// faults in fresh pages while the old copy is still held (which also set the peak memory);
// capacity beyond what is used is never touched, so a guess too high costs no resident memory,
// and one too low only leaves the last doublings.
constexpr double kMaxReservedTriangles = 3.2e7;
constexpr double kQualityGrowth = 6.0;
// A small input refined for quality alone can end a million times larger than it starts (the
// rectangle 1 x 1e-6: 2 triangles, then 2,097,152), where the guess above left its arrays to
// double twenty times: a third of that run's page faults were the copies and their fresh pages.
// There the input's feature work (termination_guard.h: 0.7 triangles per unit on the strips, 0.02
// to 2.4 on the corpus at -q30 and -q33) is the guess when it is larger. Such a mesh may have
// about as many vertices on segments as triangles (every vertex of a strip is on its sides), so
// the vertices and subsegment records get as much. Only for a few triangles: the estimate's pass
// cost guitar.poly (148 slots, 351 triangles at -q30) 4% of its run's instructions, for nothing.
constexpr double kEstimatedUpToSlots = 64;

// Returns the room reserved for new subsegment records (0 where the guess is the slots').
std::size_t reserve_for_refinement(Mesh& mesh, const RefineOptions& opt) {
  const double wanted = triangles_wanted(mesh, opt.size);
  const double slots = mesh.triangle_slots();
  double added = wanted > 0.0 ? 2.0 * wanted : opt.angle.asked() ? (kQualityGrowth - 1.0) * slots : 0.0;
  const bool estimated = wanted <= 0.0 && opt.angle.asked() && slots <= kEstimatedUpToSlots;
  if (estimated) added = std::max(added, feature_work(mesh));
  if (!(added > 0.0) || slots + added > kMaxReservedTriangles) return 0;  // let such runs grow as needed
  const std::size_t triangles = static_cast<std::size_t>(slots + added);
  const std::size_t vertices = mesh.vertex_count() + static_cast<std::size_t>(estimated ? added : added / 2.0);
  const std::size_t records = estimated ? static_cast<std::size_t>(added) : 0;
  try {
    mesh.reserve_triangles(triangles);
    mesh.points.reserve(vertices);
    mesh.kind.reserve(vertices);
    if (!mesh.marker.empty()) mesh.marker.reserve(vertices);
    mesh.subsegments.reserve(mesh.subsegments.size() + records);
  } catch (const std::bad_alloc&) {
    return 0;  // address space is short (a ulimit): grow as needed instead
  }
  return records;
}

template <class Array>
void note_array(PageWarmer& warmer, unsigned slot, const Array& a) {
  using T = typename Array::value_type;
  warmer.note(slot, a.data(), a.size() * sizeof(T), a.capacity() * sizeof(T));
}

// Whether the paper's theorems cover this run (termination_guard.h, within_proven_range): its
// algorithm as the paper analyses it, the segments split wherever they are encroached upon. A
// largest-angle bound A is covered only where -q implies it (every angle below 180 - 2 theta):
// below that no theorem says that circumcentres of obtuse triangles ever run out.
bool proven_for(const RefineOptions& opt, double input_angle) {
  const AlgorithmPolicy policy = AlgorithmPolicy::of(opt);
  if (!policy.provable || KeptBoundary(opt).active() || policy.interior_strategy != 0 || CornerLopping(opt).active())
    return false;
  if (!max_angle_implied(opt.max_angle, opt.angle)) return false;
  return within_proven_range(input_angle, opt.angle.degrees(), policy.proof_rule);
}

}  // namespace

Box extent_of(const Mesh& mesh) {
  Box box;
  for (const Point& p : mesh.points)
    if (std::isfinite(p.x) && std::isfinite(p.y)) box.add(p);
  return box;
}

// Passes over the mesh in two rounds of two, each pair of about equal cost on large inputs (45x45
// holes: 7 ms each, then 7 and 2): the feature sizes beside the input's angles and apices, then the
// Steiner cap, which needs the sizes, beside the segment pieces. With a second thread and a large
// mesh each pair runs at once, and the cap is computed before the angles say whether the proven
// range lifts it (then it is dropped); on one thread only when needed. The feature sizes are found
// once for both uses.
TerminatorStart TerminatorStart::of(const Mesh& mesh, const RefineOptions& opt) {
  TerminatorStart start;
  const bool parallel = opt.threads > 1 && mesh.triangle_slots() >= kParallelStartSlots;
  // A caller's size test asks for what is unknown in advance: memory alone caps the work then.
  const bool may_cap = opt.size_test == nullptr;
  std::vector<double> features;
  double input_angle = HUGE_VAL;
  run_both(
      parallel, [&] { features = initial_feature_sizes(mesh); },
      [&] {
        input_angle = smallest_input_angle(mesh);
        start.apices = SegmentApices(mesh);
      });
  std::optional<std::uint64_t> cap;
  // The segment pieces are made on the second thread: made on this one they raised the 45x45
  // holes' peak by 0.5-0.8 MiB (benchmarks.md, "Serial steps of the parts on two threads").
  run_both(
      parallel, [&] { start.pieces = SegmentPieces(mesh, opt.straight_chains, opt.straight_chains_at_sharp_junctions_only); },
      [&] {
        if (parallel && may_cap) cap = deltri::steiner_cap(mesh, opt.size, features);
      });
  start.proven_range = proven_for(opt, input_angle);
  start.guard_floor = guard_floor_of(mesh, opt, input_angle, features);
  // Within the proven range the theorems bound the work.
  if (start.proven_range || !may_cap) start.steiner_cap = UINT64_MAX;
  else start.steiner_cap = cap ? *cap : deltri::steiner_cap(mesh, opt.size, features);
  if (asks_memory(opt) && mesh.triangle_slots() < kProbeAfterSlots) {
    start.memory_probe_slots = mesh.triangle_slots();  // asked once the run grows (budget_left)
  } else if (const std::uint64_t memory = memory_cap(mesh.triangle_slots(), memory_budget_of(opt));
             memory < start.steiner_cap) {
    start.steiner_cap = memory;
    start.cap_kind = CapKind::Memory;
  }
  return start;
}

Terminator::Terminator(Mesh& mesh, Predicates& pred, const RefineOptions& opt)
    : Terminator(mesh, pred, opt, TerminatorStart::of(mesh, opt)) {}

Terminator::Terminator(Mesh& mesh, Predicates& pred, const RefineOptions& opt, TerminatorStart start)
    : mesh_(mesh), pred_(pred),
      opt_(opt),
      policy_(AlgorithmPolicy::of(opt)),
      rules_{opt.angle, opt.size, opt.max_angle, opt.area_field, opt.size_test},
      interior_rules_{policy_.interior_strategy != 0 ? AngleBound(std::max(opt.angle.degrees(), kInteriorBoundDeg))
                                                     : opt.angle,
                      opt.size, opt.max_angle, opt.area_field, opt.size_test},
      quick_verdict_(has_quick_verdict(rules_) && has_quick_verdict(interior_rules_)),
      lopping_(opt),
      kept_(opt),
      mending_(opt),
      optimal_points_(policy_.off_center_factor > 0.0 && opt.steiner == SteinerPolicy::Optimal),
      guard_floor_(start.guard_floor),
      proven_range_(start.proven_range),
      edge_floor_(start.proven_range && !optimal_points_ ? 0.0 : start.guard_floor),
      steiner_cap_(start.steiner_cap),
      cap_kind_(start.cap_kind),
      memory_probe_slots_(start.memory_probe_slots),
      pieces_(std::move(start.pieces)),
      apices_(std::move(start.apices)),
      finder_(mesh),
      extent_(extent_with(mesh, start.extent)),
      bottom_(mesh, opt, policy_, start.guard_floor, extent_, start.hopeless_edges),
      bad_triangles_(opt.queue_order, squared_diameter(extent_), edge_level_bits(opt.angle.degrees())),
      locked_(std::move(start.locked)),
      seams_(mesh.subseg.holds(kSeamEdge)),
      small_pages_(start.small_pages),
      warmer_(opt.threads > 1) {
  report_.guard_length = edge_floor_;
  report_.proven_range = proven_range_;
  kept_.start(mesh, opt.size.any() || opt.size_test);
  report_.hopeless_edges = bottom_.hopeless_edges();
  report_.steiner_cap = steiner_cap_;
  report_.cap_kind = cap_kind_;
  checks_stall_ = !proven_range_ && !max_angle_implied(opt.max_angle, opt.angle);
  next_stall_check_ = kStallCheckFrom;
  look_for_free_vertices();
}

// One pass over a byte per vertex, where a refinement starts (other stages make free vertices too).
void Terminator::look_for_free_vertices() {
  free_vertices_ = std::find(mesh_.kind.begin(), mesh_.kind.end(), VertexKind::Free) != mesh_.kind.end();
}

// Fig. 38, DELAUNAYTERMINATOR; l.1-2 (the CDT, exterior removed) are the caller's.
RefineReport Terminator::run() {
  refine_all();
  return finish();
}

void Terminator::split_initial_encroachments() {
  look_for_free_vertices();
  if (const std::size_t records = reserve_for_refinement(mesh_, opt_)) {
    try {
      pieces_.reserve(records);
    } catch (const std::bad_alloc&) {
      // as above: grow as needed
    }
  }
  if (small_pages_) {
    prefer_small_pages(mesh_.corner.data(), mesh_.corner.capacity() * sizeof(VertexId));
    prefer_small_pages(mesh_.link.data(), mesh_.link.capacity() * sizeof(EdgeRef));
    prefer_small_pages(mesh_.points.data(), mesh_.points.capacity() * sizeof(Point));
  }
  if (!mesh_.has_subsegments()) return;
  for (EdgeRef e : initially_encroached()) enqueue_subsegment(e);  // Fig. 38 l.3-5
  split_encroached_subsegments(false);  // Fig. 38 l.6
}

// Each subsegment tested once, from its edge with the smaller id; on a large mesh with a second
// thread the two halves of the slots at once. The list is in slot order either way.
std::vector<EdgeRef> Terminator::initially_encroached() {
  const auto scan = [this](EdgeRef from, EdgeRef to, Predicates& pred, std::vector<EdgeRef>& out) {
    for (EdgeRef e = from; e < to; ++e) {
      mesh_.subseg.fetch_ahead(e);
      if (mesh_.corner[e] == kNone || !mesh_.subseg.has(e)) continue;
      if (mesh_.link[e] != kNone && mesh_.link[e] < e) continue;
      if (is_splittable(e) && is_encroached(mesh_, pred, e, policy_.rule)) out.push_back(e);
    }
  };
  const EdgeRef edges{static_cast<std::uint32_t>(mesh_.corner.size())};
  std::vector<EdgeRef> found, upper;
  PredicateCounters upper_counted;
  run_halves(opt_.threads >= 2 && mesh_.triangle_slots() >= TerminatorStart::kParallelStartSlots, EdgeRef{0}, edges,
             [&](EdgeRef from, EdgeRef to, int half) {
               if (half == 0) return scan(from, to, pred_, found);
               Predicates upper_pred;  // counting on the worker's stack, not in a line this thread writes
               std::vector<EdgeRef> mine;
               scan(from, to, upper_pred, mine);
               upper = std::move(mine);
               upper_counted = upper_pred.counters;
             });
  pred_.counters.add(upper_counted);
  found.insert(found.end(), upper.begin(), upper.end());
  return found;
}

// Triangles split on the way are queued as they are made (queue_triangles), as after l.10 starts.
void Terminator::refine_around(std::span<const TriangleId> triangles) {
  look_for_free_vertices();
  for (TriangleId t : triangles) {
    if (t >= mesh_.triangle_slots() || !mesh_.is_live(t)) continue;
    for (EdgeRef e : edges_of(t))
      if (mesh_.subseg.has(e) && is_splittable(e) && is_encroached(mesh_, pred_, e, policy_.rule))
        enqueue_subsegment(e);
  }
  split_encroached_subsegments(true);
  for (TriangleId t : triangles)
    if (t < mesh_.triangle_slots() && mesh_.is_live(t)) enqueue_if_bad(t);
  drain_queue();
  mending_.run(*this);
}

void Terminator::drain_queue() {
  for (unsigned pops = 0; !bad_triangles_.empty(); ++pops) {  // Fig. 38 l.10
    if (pops % kWarmInterval == 0) {
      warm_pages();
      publish_progress();
    }
    prefetch_queued();
    const QueuedTriangle entry = *bad_triangles_.pop();  // Fig. 38 l.11
    count(split_bad_triangle(entry), report_);            // Fig. 38 l.12-25
    if (track_unsplit_ && is_current(mesh_, entry)) unsplit_.push_back(entry.triangle);
  }
  report_.peak_queue = std::max(report_.peak_queue, bad_triangles_.peak_size());
  publish_progress();
}

// Every kWarmInterval pops: two relaxed atomic adds, no lock and no clock.
void Terminator::publish_progress() {
  const auto vertices = static_cast<std::int64_t>(report_.interior_steiner + report_.segment_steiner) -
                        static_cast<std::int64_t>(report_.vertices_deleted);
  progress_share_.publish(opt_.progress, vertices, static_cast<std::int64_t>(bad_triangles_.size()));
}

RefineReport Terminator::finish() {
  survey_remaining();
  return report_;
}

// A bad triangle stays bad only where its turn came and it was not split (a guard refusal, or a
// Steiner point it could not have), or where the subsegments at its small angle exempt it.
std::vector<TriangleId> Terminator::unsplit_triangles() && { return std::move(unsplit_); }

TerminatorStart Terminator::hand_over() && {
  return {guard_floor_,
          proven_range_,
          steiner_cap_,
          cap_kind_,
          std::move(pieces_),
          std::move(apices_),
          std::move(locked_),
          static_cast<std::int64_t>(report_.hopeless_edges),
          false,
          extent_,
          memory_probe_slots_};
}

void Terminator::warm_pages() {
  note_array(warmer_, 0, mesh_.corner);
  note_array(warmer_, 1, mesh_.link);
  note_array(warmer_, 2, mesh_.points);
  // Where nearly every triangle carries a subsegment (a thin strip), every split appends to the
  // subsegment arrays as well, and their first touches were most of the strip's page faults.
  if (!mesh_.subseg.is_dense()) return;
  note_array(warmer_, 3, mesh_.subseg.dense_values());
  note_array(warmer_, 4, mesh_.subsegments);
  note_array(warmer_, 5, pieces_.of_subsegment);
  note_array(warmer_, 6, pieces_.splits);
}

// The queue serves triangles in size order across the whole domain, so nearly every popped
// triangle is a cache miss; its slot and corners are known well before its turn, and fetching
// them early overlaps the misses with the work on the triangles before it.
void Terminator::prefetch_queued() const {
  if (mesh_.triangle_slots() < kPrefetchFromSlots) return;
  const QueuedTriangle* next = bad_triangles_.peek(kPrefetchDistance);
  if (next == nullptr) return;
  const std::size_t e = edge_of(next->triangle, 0);
  if (e >= mesh_.corner.size()) return;
  prefetch(&mesh_.corner[e]);
  prefetch(&mesh_.link[e]);
  if (mesh_.has_subsegments()) prefetch(mesh_.subseg.bits_at(e));
  for (VertexId v : {next->a, next->b, next->c})
    if (v < mesh_.vertex_count()) prefetch(&mesh_.points[v]);
  // Half as far ahead the entry's links have arrived, and its neighbours are what the cavity
  // search reads first.
  const QueuedTriangle* nearer = bad_triangles_.peek(kPrefetchDistance / 2);
  if (nearer == nullptr) return;
  const TriangleId t = nearer->triangle;
  if (edge_of(t, 0) >= mesh_.corner.size()) return;
  for (const EdgeRef e : edges_of(t)) {
    if (const EdgeRef twin = mesh_.link[e]; twin != kNone) prefetch(mesh_.corners_at(twin.triangle()));
    // The table entry of a subsegment beside it, which a split reads (its bits came with the
    // farther fetch): on a strip every triangle has one, each entry a miss in a table of megabytes.
    if (mesh_.has_subsegments() && mesh_.subseg.has(e)) prefetch(mesh_.subseg.home_of(e));
  }
}

// A split appends two triangles (none is free while nothing is deleted) and puts a subsegment on
// the first one's slot: the table entries of their slots' blocks, a miss for each new block, are
// fetched while the split is planned.
void Terminator::prefetch_new_subsegment_homes() const {
  if (!mesh_.free_triangles.empty()) return;
  const std::size_t e = edge_of(TriangleId{mesh_.triangle_slots()}, 0);
  prefetch(mesh_.subseg.home_of(e));
  prefetch(mesh_.subseg.home_of(e + 3));
}

// assess_with's exemptions need an angle of t between two subsegments, a corner lopped
// (--corner-lopping), or a shortest edge both of whose ends lie on segments (shell_exempt).
inline bool Terminator::cannot_be_exempt(TriangleId t, const SideMeasures& m) const {
  if (lopping_.active()) return false;
  if (mesh_.has_subsegments() &&
      mesh_.subseg.has(edge_of(t, 0)) + mesh_.subseg.has(edge_of(t, 1)) + mesh_.subseg.has(edge_of(t, 2)) > 1)
    return false;
  const VertexId* c = mesh_.corners_at(t);
  const unsigned s = shortest_side(m.length2);
  return !may_lie_on_piece(c[s]) || !may_lie_on_piece(c[(s + 1) % 3]);
}

// Most triangles around a new vertex are cleared by surely_good or, where no exemption can apply,
// judged by queue_badness; the full assessment is for the rest (a third of those queued on
// islands.poly at -q30).
void Terminator::enqueue_if_bad(TriangleId t) {
  const Criteria& rules = rules_for(t);
  const SideMeasures m = side_measures(mesh_, t);
  if (quick_verdict_) {
    if (surely_good(m, rules)) return;
    if (cannot_be_exempt(t, m)) {
      if (Badness why; queue_badness(m, rules, why)) {
        const VertexId* c = mesh_.corners_at(t);
        bad_triangles_.push({t, c[0], c[1], c[2]}, why);
      }
      return;
    }
  }
  const Assessment a = assess_with(t, rules, m);
  if (!a.bad()) return;
  DELTRI_ASSERT(mesh_.is_live(t));
  const auto [u, v, w] = mesh_.corners(t);
  const QueuedTriangle entry{t, u, v, w};
  bad_triangles_.push(entry, {a.skinny, a.shape.ratio2_over_bound2, a.shape.shortest_length2});
}

// Vertex attributes are interpolated linearly over the triangle the point falls in.
VertexId Terminator::add_free_vertex(const Point& p, EdgeRef container) {
  const VertexId v = mesh_.add_vertex(p, VertexKind::Free);
  free_vertices_ = true;
  const int na = mesh_.num_attributes;
  if (na == 0) return v;
  const TriangleId t = triangle_of(container);
  const auto [a, b, c] = mesh_.corners(t);
  const Point &pa = mesh_.point(a), &pb = mesh_.point(b), &pc = mesh_.point(c);
  const double area = (pb.x - pa.x) * (pc.y - pa.y) - (pb.y - pa.y) * (pc.x - pa.x);
  const double wb = ((p.x - pa.x) * (pc.y - pa.y) - (p.y - pa.y) * (pc.x - pa.x)) / area;
  const double wc = ((pb.x - pa.x) * (p.y - pa.y) - (pb.y - pa.y) * (p.x - pa.x)) / area;
  for (int k = 0; k < na; ++k) {
    const auto at = [&](VertexId u) { return mesh_.attributes[static_cast<std::size_t>(u) * na + k]; };
    mesh_.attributes[static_cast<std::size_t>(v) * na + k] =
        at(a) + wb * (at(b) - at(a)) + wc * (at(c) - at(a));
  }
  return v;
}

Point Terminator::centroid_of(TriangleId t) const {
  const auto [p, q, r] = mesh_.corner_points(t);
  return Point{(p.x + q.x + r.x) / 3.0, (p.y + q.y + r.y) / 3.0};
}

// Takes back a vertex that was added to mesh.points but never made it into the triangulation.
void Terminator::drop_last_vertex() {
  mesh_.points.pop_back();
  mesh_.kind.pop_back();
  if (!mesh_.marker.empty()) mesh_.marker.pop_back();
  if (mesh_.num_attributes > 0) mesh_.attributes.resize(mesh_.attributes.size() - mesh_.num_attributes);
}

void Terminator::enqueue_subsegment(EdgeRef e) {
  DELTRI_ASSERT(mesh_.subseg.has(e));
  encroached_.push({e, mesh_.org(e), mesh_.dest(e)});
}

EdgeRef Terminator::current_edge(const EncroachedSubsegment& entry) {
  const auto is_it = [&](EdgeRef e) {
    if (e == kNone || e >= mesh_.corner.size() || !mesh_.is_live(triangle_of(e))) return false;
    if (!mesh_.subseg.has(e)) return false;
    const VertexId o = mesh_.org(e), d = mesh_.dest(e);
    return (o == entry.a && d == entry.b) || (o == entry.b && d == entry.a);
  };
  if (is_it(entry.edge)) return entry.edge;
  const EdgeRef found = finder_.find(mesh_, entry.a, entry.b);
  return is_it(found) ? found : kNone;
}

bool Terminator::is_splittable(EdgeRef e) const {
  if (kept_.keeps(mesh_, e)) return false;
  if (lopping_.is_spoke(mesh_, e)) return false;
  if (!seams_ && locked_.empty()) return true;
  const SubsegmentId id = mesh_.subseg[e];
  if (id == kSeamEdge) return false;
  return id >= locked_.size() || !locked_[id];
}

// A subsegment that doubles cannot split (the split point rounds onto an end, or a neighbour lies
// flush with it there) is treated as -Y treats the boundary from then on. Trying again only
// repeated the failure, and where Chew's step had deleted free vertices first, their triangles came
// back with new ones: robustness1.node at -a0.93 went round that loop 177,000 times, to the Steiner
// cap (361,425 points, 354,083 deletions).
void Terminator::lock(EdgeRef s) {
  const SubsegmentId id = mesh_.subseg[s];
  if (id >= locked_.size()) locked_.resize(mesh_.subsegments.size(), 0);
  locked_[id] = 1;
}

// -D (AlgorithmPolicy::retries_locks, algorithm_ruppert.cpp): the locked subsegments left encroached
// are unlocked and split where doubles now can, in rounds while some split.
void Terminator::retry_locked_encroachments() {
  for (int round = 0; round < kLockRetryRounds; ++round) {
    bool any = false;
    for (EdgeRef e{0}; e < mesh_.corner.size(); ++e) {
      if (!mesh_.is_live(triangle_of(e)) || !mesh_.subseg.has(e)) continue;
      if (mesh_.link[e] != kNone && mesh_.link[e] < e) continue;
      const SubsegmentId id = mesh_.subseg[e];
      if (id >= locked_.size() || !locked_[id] || !is_encroached(mesh_, pred_, e, policy_.rule)) continue;
      locked_[id] = 0;
      if (!is_splittable(e)) {
        locked_[id] = 1;
        continue;
      }
      if (report_.locked_subsegments > 0) --report_.locked_subsegments;  // counted again if locked again
      enqueue_subsegment(e);
      any = true;
    }
    if (!any || split_encroached_subsegments(true) == 0) return;
    drain_queue();
  }
}

// A segment vertex takes the segment's marker and attributes interpolated along the subsegment.
VertexId Terminator::add_segment_vertex(const Point& p, EdgeRef s) {
  const VertexId a = mesh_.org(s), b = mesh_.dest(s);
  const VertexId v = mesh_.add_vertex(p, VertexKind::Segment);
  if (!mesh_.marker.empty()) mesh_.marker[v] = mesh_.subsegments[mesh_.subseg[s]].marker;
  mesh_.interpolate_attributes(v, a, b);
  return v;
}

}  // namespace deltri
