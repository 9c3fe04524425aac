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
// subsegments. Only these carry concentric shells and clusters; refinement never adds one.
class SegmentApices {
 public:
  SegmentApices() = default;
  explicit SegmentApices(const Mesh& mesh);
  bool is_apex(VertexId v) const { return v < apex_.size() && apex_[v]; }

 private:
  std::vector<bool> apex_;
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
