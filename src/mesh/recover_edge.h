// Makes a segment u-v an edge of a constrained Delaunay triangulation when nothing but unconstrained
// edges separates u from v.
//
// Method (Sloan 1993, "A fast algorithm for generating constrained Delaunay triangulations"):
// flip crossed edges whose quadrilateral is strictly convex until none crosses u-v (one always
// is convex while any crosses, so this terminates), then Lawson-flip the edges inside the cavity
// (the triangles that were crossed; flips reuse their slots, so the set stays put) until each is
// locally Delaunay. Triangles outside the cavity stay constrained Delaunay when a constraint is
// added, so the result is the constrained Delaunay triangulation. Flips cope with cavities that
// touch themselves at a vertex, which recursive polygon retriangulation handles only with care.
//
// A kernel operation (it flips and attaches a subsegment): the constrained Delaunay stage calls it
// through SegmentInserter. The Lawson pass is the kernel's one routine, confined to the cavity.
#pragma once

#include <cstdint>
#include <vector>

#include "mesh/constrained_editor.h"

namespace deltri {

class EdgeRecovery {
 public:
  explicit EdgeRecovery(ConstrainedEditor& editor) : ed_(editor) {}

  // `crossed` lists every edge crossing the open segment u-v (none carrying a subsegment, no
  // vertex on the open segment). Makes u-v an edge carrying subsegment `id` and returns it (either
  // direction), or kNone if the mesh was not what the contract says.
  EdgeRef recover(VertexId u, VertexId v, const std::vector<EdgeRef>& crossed, SubsegmentId id);

 private:
  bool crosses(EdgeRef e, VertexId u, VertexId v);
  void remove_crossings(VertexId u, VertexId v, const std::vector<EdgeRef>& crossed);
  void restore_delaunay();
  bool in_cavity(TriangleId t) const { return t < stamp_.size() && stamp_[t] == round_; }

  ConstrainedEditor& ed_;
  std::vector<std::uint32_t> stamp_;  // stamp_[t] == round_: t is in the current cavity
  std::uint32_t round_ = 0;
  std::vector<TriangleId> cavity_;
  // A crossing edge waiting in Sloan's FIFO: its ends, and the slot it was seen at (a flip of a
  // neighbour may have moved it since; then the vertex map finds it again).
  struct Crossing {
    VertexId a, b;
    EdgeRef seen;
  };
  std::vector<Crossing> queue_;  // the FIFO, from the loop's head on
  // The edge a->b of a waiting crossing.
  EdgeRef edge_of_crossing(const Crossing& c);
  std::vector<EdgeRef> stack_;
};

}  // namespace deltri
