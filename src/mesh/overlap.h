// Whether the live triangles of a mesh form a triangulation in the plane: no two overlap and no
// corner of one lies on another that it is not a corner of (a T-junction). Twins, orientation
// and unique directed edges (what -r and -C check first) do not imply this: two counter-clockwise
// triangles can cross without sharing an edge, or a whole second sheet can lie over the first.
//
// find_overlap first tries mesh/embedding.h's certificate, linear for ordinary meshes (fans and
// slivers included), which proves that there is nothing to find. Only when it is refused (a vertex
// where two fans touch, boundary edges that meet, loops nested wrongly, or its budget exceeded)
// does the pair search run, which also names the pair: the triangles' boxes are bucketed on a
// grid (geometry/box_pairs.h) and each pair whose boxes meet is tested once with exact orient2d:
// two counter-clockwise triangles have disjoint interiors exactly when an edge line of one has the
// other on its closed outer side (separating axes), and a corner of u on the closed triangle t
// that is not a corner of t is on t's boundary or inside it. The search's time grows with the
// number of pairs whose boxes meet, quadratic on long slivers (docs/reliability.md, finding 10).
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

// The pair search alone, without the certificate (the same answer; for tests).
std::optional<OverlapFinding> search_overlap(const Mesh& mesh, Predicates& pred);

}  // namespace deltri
