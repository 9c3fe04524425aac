// Vertex relocation in the second stage of locally optimal points (docs/refinement.md, "Locally
// optimal Steiner points", "-q40 and above"): before a bad triangle gets a new vertex, each of its
// free corners may move to where its star's smallest angle is larger. Above about 38 degrees a new
// vertex rarely has a place where all its new triangles meet the bound (ring.poly at -q40: no such
// candidate in 445 of 530 petal searches), so each insertion leaves bad triangles and the inserting
// cascades; a move changes no topology and makes no shorter edge. A move is kept only where
//   * the star stays a valid fan (exact orient2d) and its smallest angle rises;
//   * every edge of the star stays locally Delaunay (exact incircle), edges on subsegments
//     excepted, which the vertex must not encroach upon (the refinement's rule);
// so the mesh stays the constrained Delaunay mesh the Terminator keeps. The search is a compass
// search on the star's smallest angle (as --smooth's, improve/smooth.cpp, whose layer comes after
// refinement): eight directions at a tenth of the shortest spoke, halved when none gains.
#pragma once

#include <vector>

#include "geometry/encroachment.h"
#include "geometry/mesh_bounds.h"
#include "geometry/predicates.h"
#include "mesh/mesh.h"
#include "mesh/star.h"

namespace deltri {

// Moves per vertex of the mesh a run may make: moves add no vertex, so the Steiner cap does not
// bound them. Raising it from 4 to 16 changed no file's outcome at -q40 (measured with the
// shortest-edge order; refinement.md).
inline constexpr double kRelocationsPerVertex = 4.0;

// What a move raises: the star's smallest angle, or, for a triangle bad only for an angle above
// --max-angle whose point the guard refused, the star's least margin against both angle bounds
// (criteria.h, angle_margin), so that an obtuse corner can open up without a new vertex.
struct StarGoal {
  const AngleBound* angle = nullptr;             // null: the smallest angle alone
  const LargestAngleBound* max_angle = nullptr;
};

class Relocator {
 public:
  // Moves org(first), a free vertex, to raise its star's measure under `goal`; true when it moved.
  // The star's edges leaving it are in star_edges() afterwards.
  bool relocate(Mesh& mesh, Predicates& pred, const EncroachRule& rule, EdgeRef first, StarGoal goal = {});
  const std::vector<EdgeRef>& star_edges() const { return star_.out; }

 private:
  // sin^2 of the smallest angle of the star with its centre at p, or some value at or below floor
  // once that is below it (a candidate no better than floor is dropped whatever its exact measure).
  double least_angle(const Point& p, double floor) const;
  double measure(const Point& p, double floor) const;  // least_angle, or the least margin under goal_
  void read_rim(const Mesh& mesh);
  bool acceptable(const Mesh& mesh, Predicates& pred, const EncroachRule& rule, const Point& p, double before) const;
  Star star_;  // the moving vertex's star (mesh/star.h)
  std::vector<Point> rim_;     // the points of star_.ring
  std::vector<double> rim2_;   // rim2_[i]: |rim_[i] rim_[i + 1]|^2
  mutable std::size_t worst_ = 0;  // where least_angle found the smallest last (where it starts)
  StarGoal goal_;                  // the current move's
};

}  // namespace deltri
