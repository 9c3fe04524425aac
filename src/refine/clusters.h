// Subsegment clusters (Sec. 6.3, Fig. 29): at an apex where segments meet, the subsegments that
// are separated from one another by 60 degrees or less, measured inside the triangulation domain
// (angles across holes or the exterior do not count). Once split to power-of-two lengths the
// members of a cluster encroach on each other and are split as a unit, so splitting one creates
// a free edge of length |s| sin(phi_min / 2) opposite the smallest angle.
#pragma once

#include <vector>

#include "mesh/mesh.h"

namespace deltri {

// The apices: vertices present before refinement that are the endpoint of two or more
// subsegments. Only these carry clusters; refinement never adds one.
//
// Concentric shells are used only at the acute apices: two subsegments that follow each other
// around the apex inside the domain at less than 90 degrees. At 90 degrees or more the midpoint
// of one never encroaches on the other, whatever their lengths, so the cycle of Fig. 24 cannot
// start there; and midpoints keep the split points of a long side out of step with those of the
// side facing it across a thin channel, where shells measured from both corners line them up into
// right triangles that fail the bound and split again (Triangle 1.6 likewise splits at midpoints
// away from segments that share a triangle). Clusters (60 degrees or less) are acute apices.
class SegmentApices {
 public:
  SegmentApices() = default;
  explicit SegmentApices(const Mesh& mesh);
  bool is_apex(VertexId v) const { return v < apex_.size() && apex_[v]; }
  bool uses_shells(VertexId v) const { return v < shells_.size() && shells_[v]; }
  // Exactly two segments end at v (a corner, not a cluster of three or more).
  bool is_two_segment_corner(VertexId v) const { return v < corner_.size() && corner_[v]; }
  // The same marks for a part that holds only `vertices` (increasing), renumbered from 0.
  SegmentApices of_vertices(const std::vector<VertexId>& vertices) const;

 private:
  std::vector<bool> apex_;
  std::vector<bool> shells_;
  std::vector<bool> corner_;
};

struct Cluster {
  std::vector<EdgeRef> members;  // edges leaving the apex, the starting one first
  double min_separation = 0.0;   // radians, the smallest angle between two neighbouring members
  bool in_cluster() const { return members.size() >= 2; }
};

// The cluster containing the subsegment on edge `from_apex` (whose origin is the apex), found by
// turning around the apex through triangles in both directions and stopping at gaps over 60
// degrees or at the domain boundary.
Cluster subsegment_cluster(const Mesh& mesh, EdgeRef from_apex);

}  // namespace deltri
