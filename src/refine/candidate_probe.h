// Fig. 38 l.13-14 without touching the mesh: where would a Steiner point c go, which subsegments
// would it encroach upon, and how short would its new edges be?
//
// The paper suggests inserting c, looking at the edges opposite it, and undoing the flips if c is
// rejected. Looking is enough: in a constrained Delaunay triangulation the triangles that the
// insertion of c destroys are exactly those reachable from the triangle containing c across
// non-subsegment edges whose circumcircles strictly contain c (the same strict incircle test
// Lawson's flips use), and the edges opposite c afterwards are the boundary of that cavity. So a
// rejected point leaves the mesh and both queues exactly as they were, with nothing to undo.
//
// Locating c walks the straight line from the centroid of the bad triangle towards c (Appendix
// A); a subsegment blocking the walk is encroached upon, whatever the encroachment rule.
#pragma once

#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include "geometry/predicates.h"
#include "mesh/mesh.h"
#include "mesh/operations.h"
#include "refine/encroached.h"
#include "util/invariant.h"
#include "util/small_vector.h"

namespace deltri {

enum class ProbeStatus {
  Clear,       // c can be inserted: it lies in the mesh and encroaches upon nothing
  Encroaches,  // c encroaches upon `encroached` (a blocking subsegment is listed alone)
  Unusable,    // c coincides with a vertex, lies on or behind a subsegment that may not be
               // split (blocked), or leaves the mesh through an unprotected edge
};

// The subsegments a candidate encroaches upon: one or two nearly always (a strip's rejected
// circumcentre, one per side), kept in place; more spill to the heap. A probe runs for every bad
// triangle, and an allocation for each rejected one cost a tenth as much as the probe itself.
using EncroachedEdges = SmallVector<EdgeRef, 4>;

struct Probe {
  ProbeStatus status = ProbeStatus::Unusable;
  EdgeRef container = kNone;           // an edge of the triangle containing c (Clear only)
  bool strictly_inside = false;        // c is inside that triangle, not on its sides (Clear only)
  bool blocked = false;                // the walk stopped at a subsegment or the boundary
  EncroachedEdges encroached;          // edges carrying the encroached subsegments
  double insertion_radius = 0.0;       // distance from c to the nearest vertex it would join
};

// Reusable triangle marks for the cavity search, its work list and what it found (reused so that
// a search, which runs for every candidate point, allocates nothing). A cavity is a handful of
// triangles, so the marks of a search are a short list first and spill to a hash set only when it
// grows (per-slot stamps, an array as long as the mesh, cost 4 bytes per triangle at the peak).
class CavityMarks {
 public:
  void begin();
  bool mark(TriangleId t);  // false if already marked in this search
  // mark, for a t known not to be marked yet. add and contains are inline: the cavity search asks
  // them about fifteen times a cavity, and a cavity is nearly always a short list.
  void add(TriangleId t) {
    ++count_;
    if (!stamped_ && listed_ < kListLimit) {
      list_[listed_++] = t;
      listed_bits_ |= std::uint64_t{1} << (t % 64);
      return;
    }
    add_spilled(t);
  }
  bool contains(TriangleId t) const {
    if (stamped_) return marked().contains(t);
    if ((listed_bits_ >> (t % 64) & 1) == 0) return false;
    for (std::size_t i = 0; i < listed_; ++i)
      if (list_[i] == t) return true;
    return false;
  }
  // The triangles marked by the latest search and the boundary it recorded, valid until the next
  // begin().
  KnownCavity marked() const;
  std::vector<TriangleId>& todo() { return todo_; }
  // The search records the cavity's boundary edges, separately those of them that carry
  // subsegments, and the cavity's triangles that have no boundary edge.
  std::vector<EdgeRef>& boundary() { return boundary_; }
  std::vector<EdgeRef>& boundary_subsegments() { return boundary_subsegments_; }
  std::vector<TriangleId>& inner() { return inner_; }

 private:
  static constexpr std::size_t kListLimit = 32;
  void spill();
  void add_spilled(TriangleId t);  // add beyond the list
  void insert_spilled(TriangleId t);  // into the hash set, growing it past half full
  TriangleId list_[kListLimit];
  std::size_t listed_ = 0;
  std::uint64_t listed_bits_ = 0;  // bit t % 64 set for each listed t: most lookups miss, in one test
  bool stamped_ = false;  // this search has spilled to the hash set
  std::vector<TriangleId> table_;    // the hash set (KnownCavity), all kNone between searches
  unsigned table_bits_ = 0;
  std::vector<TriangleId> spilled_;  // its members, to empty it and to grow it
  std::vector<TriangleId> todo_;
  std::vector<EdgeRef> boundary_;
  std::vector<EdgeRef> boundary_subsegments_;
  std::vector<TriangleId> inner_;
  std::size_t count_ = 0;  // triangles marked
};

// Probes point c for a bad triangle t. `splittable(e)` says whether the subsegment on edge e may
// be split at all (-Y); encroachment of unsplittable subsegments is not reported, except that a
// walk they block makes c Unusable.
template <class Splittable>
Probe probe_candidate(const Mesh& mesh, Predicates& pred, TriangleId t, const Point& c,
                      const EncroachRule& rule, CavityMarks& marks, Splittable&& splittable);

// The insertion radius of a point c on the subsegment carried by edge s (a segment split).
double split_insertion_radius(const Mesh& mesh, Predicates& pred, EdgeRef s, const Point& c,
                              CavityMarks& marks);

namespace detail {

struct WalkResult {
  EdgeRef container = kNone;  // an edge of the closed triangle containing c
  EdgeRef blocker = kNone;    // the edge the walk could not cross
  bool on_vertex = false;
  bool on_edge = false;  // c is on a side of the container
};
WalkResult walk_towards(const Mesh& mesh, Predicates& pred, TriangleId t, const Point& c);

// Marks the triangles that inserting c destroys and records the cavity's boundary; returns the
// squared distance from c to the nearest cavity vertex.
double cavity_of(const Mesh& mesh, Predicates& pred, std::span<const TriangleId> seeds,
                 const Point& c, CavityMarks& marks);

}  // namespace detail

template <class Splittable>
Probe probe_candidate(const Mesh& mesh, Predicates& pred, TriangleId t, const Point& c,
                      const EncroachRule& rule, CavityMarks& marks, Splittable&& splittable) {
  Probe probe;
  const detail::WalkResult walk = detail::walk_towards(mesh, pred, t, c);
  if (walk.on_vertex) return probe;
  if (walk.blocker != kNone) {
    probe.blocked = true;
    if (!mesh.has_subsegments() || !mesh.subseg.has(walk.blocker) || !splittable(walk.blocker))
      return probe;
    probe.status = ProbeStatus::Encroaches;
    probe.encroached.push_back(walk.blocker);
    return probe;
  }
  const TriangleId seed = triangle_of(walk.container);
  probe.insertion_radius = std::sqrt(detail::cavity_of(mesh, pred, {&seed, 1}, c, marks));
  for (EdgeRef e : marks.boundary_subsegments()) {
    const Point& a = mesh.point(mesh.org(e));
    const Point& b = mesh.point(mesh.dest(e));
    if (splittable(e)) {
      if (encroaches(pred, a, b, c, rule)) probe.encroached.push_back(e);
    } else if (pred.orient2d(a, b, c) == 0) {  // on a subsegment that may not be split
      probe.blocked = true;
      return probe;
    }
  }
  probe.container = walk.container;
  probe.strictly_inside = !walk.on_edge;
  probe.status = probe.encroached.empty() ? ProbeStatus::Clear : ProbeStatus::Encroaches;
  DELTRI_ASSERT(probe.status != ProbeStatus::Clear || mesh.is_live(triangle_of(probe.container)));
  return probe;
}

}  // namespace deltri
