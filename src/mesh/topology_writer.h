// Write access to the topology arrays (Mesh::corner, link, subseg) for the kernel's operations in
// src/mesh/ and the divide-and-conquer builder, which fills the arrays by hand (issue 20). Nothing
// else includes this header (tests/mesh/topology_writers.sh checks); tests that break a mesh on
// purpose, to see the checks catch it, use it too.
#pragma once

#include "mesh/mesh.h"

namespace deltri::detail {

struct TopologyWriter {
  static BigVector<VertexId>& corner(Mesh& m) { return m.corner.slots_; }
  static BigVector<EdgeRef>& link(Mesh& m) { return m.link.slots_; }
  static SubsegmentSlots::Editor subseg(Mesh& m) { return SubsegmentSlots::Editor(m.subseg); }
};

// The writable arrays of m: corner_slots(m)[e] = v, subseg_slots(m).set(e, s).
inline BigVector<VertexId>& corner_slots(Mesh& m) { return TopologyWriter::corner(m); }
inline BigVector<EdgeRef>& link_slots(Mesh& m) { return TopologyWriter::link(m); }
inline SubsegmentSlots::Editor subseg_slots(Mesh& m) { return TopologyWriter::subseg(m); }

}  // namespace deltri::detail
