// Whether the live triangles of a mesh form a triangulation in the plane: no two overlap and no
// corner of one lies on another that it is not a corner of (a T-junction). Twins, orientation
// and unique directed edges (what -r and -C check first) do not imply this: two counter-clockwise
// triangles can cross without sharing an edge, or a whole second sheet can lie over the first.
//
// The triangles are bucketed on a uniform grid of about two cells per triangle, and each pair
// whose bounding boxes meet is tested once (in the cell holding the lower-left corner of the
// boxes' intersection) with exact orient2d: two counter-clockwise triangles have disjoint
// interiors exactly when an edge line of one has the other on its closed outer side (separating
// axes), and a corner of u on the closed triangle t that is not a corner of t is on t's boundary
// or inside it. Linear time on meshes whose triangles are of similar size; on long slivers whose
// boxes overlap (a fan of n triangles from one vertex, slivers crowded at a crossing) the number
// of pairs to test, and so the time, grows as n^2 (docs/reliability.md, open finding 10).
#pragma once

#include <optional>

#include "geometry/predicates.h"
#include "mesh/mesh.h"

namespace deltri {

struct OverlapFinding {
  TriangleId first = kNone, second = kNone;
  bool interiors_overlap = false;  // otherwise a corner of one lies on the other's boundary
};

// The first offending pair found (first < second), or nothing. The live triangles must be
// strictly counter-clockwise with corners in range, and no directed edge may be in two triangles.
std::optional<OverlapFinding> find_overlap(const Mesh& mesh, Predicates& pred);

}  // namespace deltri
