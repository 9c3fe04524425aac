// The mesh improvement pass (--smooth[=N]): after refinement, moves each free vertex (a Steiner
// point refinement put in the interior, VertexKind::Free) towards its optimal Delaunay
// triangulation position, the area-weighted mean of the circumcentres of its star (Chen and Xu's
// ODT update), and keeps a move only where nothing gets worse (docs/refinement.md, "Mesh
// improvement (--smooth)"):
//   * the star stays a valid fan: every triangle strictly counter-clockwise (exact orient2d);
//   * the star's smallest angle rises (by more than the rounding of its measure);
//   * every triangle of the star still meets the -q angle, the -a area (and its own area bound:
//     bare -a, regions, .area), the -u edge length and a caller's size test;
//   * the mesh stays constrained Delaunay: every edge of the star that carries no subsegment (with
//     -D every edge) is locally Delaunay by exact incircle; the other edges are untouched.
// A star that misses a bound before the move (near a small input angle) is left alone, so the
// account of misses cannot change. No topology changes: only coordinates move, so vertices on
// segments, input vertices, attributes and markers stay as they are. Single-threaded in vertex id
// order, so the result is the same for every thread count.
#pragma once

#include <cstdint>

#include "geometry/mesh_bounds.h"
#include "geometry/predicates.h"
#include "mesh/mesh.h"
#include "refine/size_test.h"

namespace deltri {

struct SmoothOptions {
  int rounds = 3;                        // passes over the free vertices (a pass that moves none ends early)
  AngleBound angle;                      // -q
  SizeBounds size;                       // -a, bare -a / regions / .area, -u
  LargestAngleBound max_angle;           // --max-angle
  const SizeTest* size_test = nullptr;   // a caller's size test (-u's callback, --size-field)
  bool conforming = false;               // -D: segment edges must stay Delaunay as well
};

struct SmoothReport {
  int rounds = 0;              // passes made
  std::uint64_t tried = 0;     // free vertices looked at, summed over the passes
  std::uint64_t moved = 0;     // moves accepted, summed over the passes
};

SmoothReport smooth_mesh(Mesh& mesh, Predicates& pred, const SmoothOptions& opt);

}  // namespace deltri
