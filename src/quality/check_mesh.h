// The -C consistency check: verifies the invariants listed in mesh/mesh.h, in layers that each
// assume the ones before them (as CGAL's is_valid does), so that a broken layer never makes a later
// one index out of range or report nonsense:
//
//   storage      array sizes, ids in range, distinct corners, the free list
//   topology     twins (link), unique directed edges, subsegments on twins, no dead vertex in use
//   orientation  every triangle strictly counter-clockwise (exact orient2d), then no two
//                triangles overlapping or meeting other than at shared corners (mesh/overlap.h)
//   boundary     boundary edges (link == kNone) close up into loops
//   delaunay     unconstrained interior edges locally Delaunay (exact incircle)
//   convex hull  optional: one convex boundary loop and every input vertex in use
//
// A layer whose prerequisites found faults is skipped and the report says so. Every geometric
// decision is exact; nothing uses a tolerance.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>

#include "mesh/mesh.h"

namespace deltri {

struct CheckOptions {
  // Segment edges must be locally Delaunay too (conforming Delaunay, -D), not only free edges.
  bool conforming = false;
  // The mesh triangulates a plain point set (no segments, no holes): its boundary must be one
  // convex loop and every vertex of kind Input must be a corner of some triangle.
  bool convex_hull_expected = false;
};

enum class CheckLayer : std::uint8_t { Storage, Topology, Orientation, Boundary, Delaunay, ConvexHull };
inline constexpr std::size_t kCheckLayers = 6;

// One kind of fault. The count of a kind is in the unit named by fault_subject().
enum class FaultKind : std::uint8_t {
  // storage
  ArraySize,           // an array whose length disagrees with the others (subject: none)
  CornerOutOfRange,    // a live triangle names a vertex that does not exist (triangle)
  RepeatedCorner,      // a live triangle uses one vertex twice (triangle)
  BadFreeListEntry,    // a free-list entry out of range, live or listed twice (triangle)
  UnlistedDeadSlot,    // a dead slot missing from the free list (triangle)
  LinkOutOfRange,      // link[e] names no edge slot (edge)
  SubsegmentOutOfRange,  // subseg[e] names no subsegment (edge)
  // topology
  LinkToDeadTriangle,  // a live edge linked into a dead slot (edge)
  LinkNotInvolution,   // link[link[e]] != e (edge)
  LinkEndpoints,       // twins whose endpoints are not swapped (edge)
  DuplicateEdge,       // a directed edge that an earlier live triangle has already (edge)
  SubsegmentMismatch,  // twins carrying different subsegments (edge pair)
  SubsegmentEndpoints, // an edge carrying a subsegment with other endpoints (edge, once per pair)
  DeadVertexUsed,      // a vertex of kind Duplicate or Dead used by a triangle (vertex)
  // orientation
  ClockwiseTriangle,   // (triangle)
  FlatTriangle,        // three collinear corners (triangle)
  // boundary
  OpenBoundary,        // a vertex where boundary edges arrive and leave unequally often (vertex)
  // delaunay
  NotLocallyDelaunay,  // the twin's apex strictly inside the circumcircle (edge pair)
  // convex hull
  ReflexBoundaryTurn,  // consecutive boundary edges turning clockwise (the second edge)
  ExtraBoundaryLoop,   // boundary loops beyond the first (one per extra loop; example: an edge)
  UnusedVertex,        // an Input vertex in no triangle (vertex)
  // orientation, run only when the rest of that layer and the topology are sound
  OverlappingTriangles,  // two triangles overlap or meet other than at shared corners (triangle)
};
inline constexpr std::size_t kFaultKinds = 22;

// A short description of the fault kind, e.g. "link is not an involution".
const char* fault_name(FaultKind kind);
// What the example id of the kind names: "triangle", "edge", "vertex" or "" (no example).
const char* fault_subject(FaultKind kind);
// The layer that detects the kind.
CheckLayer fault_layer(FaultKind kind);
const char* layer_name(CheckLayer layer);

struct CheckReport {
  std::array<std::uint64_t, kFaultKinds> counts{};
  // The first offending id met for each kind, or kNone.
  std::array<std::uint32_t, kFaultKinds> examples = filled_with_none();
  // Layers not run because a layer they rely on found faults. (The convex hull layer is simply
  // not run, and not marked skipped, when CheckOptions does not ask for it.)
  std::array<bool, kCheckLayers> skipped{};
  std::uint32_t triangles_checked = 0;
  std::uint64_t edges_checked = 0;   // undirected edges of live triangles
  std::uint32_t boundary_loops = 0;  // only counted when the convex hull layer runs

  void record(FaultKind kind, std::uint32_t where);
  std::uint64_t count(FaultKind kind) const { return counts[static_cast<std::size_t>(kind)]; }
  std::uint32_t example(FaultKind kind) const { return examples[static_cast<std::size_t>(kind)]; }
  std::uint64_t total_faults() const;
  bool layer_skipped(CheckLayer layer) const { return skipped[static_cast<std::size_t>(layer)]; }
  bool ok() const { return total_faults() == 0; }
  // One line per fault kind present (count and example), then the skipped layers; a single
  // "consistent" line when there is nothing to report.
  std::string summary() const;

 private:
  static std::array<std::uint32_t, kFaultKinds> filled_with_none() {
    std::array<std::uint32_t, kFaultKinds> a;
    a.fill(kNone);
    return a;
  }
};

// Checks `mesh`; never modifies it and never throws on a malformed mesh (only bad_alloc).
CheckReport check_mesh(const Mesh& mesh, const CheckOptions& opt);

}  // namespace deltri
