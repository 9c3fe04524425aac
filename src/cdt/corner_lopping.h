// Corner-lopping (Shewchuk 2001, Sec. 6.1, Fig. 22; Bern, Eppstein and Gilbert, Ruppert): the
// input PSLG X becomes X' by shielding each apex a of an input angle under 60 degrees inside the
// domain. The shield is the circle of radius lfs(a)/3 around a (lfs from the nearest feature not
// incident to a: another vertex or a segment without a as an end); a vertex goes where the circle
// meets each segment at a, the arcs between them that lie inside the domain and span over 60
// degrees are cut into equal arcs of at most 60 degrees, and the chords (shield edges) become
// segments. The lopped corner is filled at once with its fan: the spoke edges from a to the arc
// vertices are segments too, so that the triangles inside the shield are exactly the fan, and
// refinement leaves them alone (RefineOptions::lopped_apices) while it meshes X' around them.
// Chords and spokes are internal: forget_lopping_edges drops them before output, whose segments
// are then those of X, split.
#pragma once

#include <cstdint>
#include <vector>

#include "mesh/mesh.h"
#include "pslg/pslg.h"

namespace deltri {

struct CornerLopping {
  std::vector<char> apex;           // by vertex id: a lopped apex (the centre of a fan)
  std::vector<char> internal;       // by segment index of the changed PSLG: a chord or spoke
  std::uint32_t apices = 0;         // how many corners were lopped
  double shortest_radius = 0.0;     // the smallest shield radius, lfs(a)/3 (0 if none)
};

// Changes pslg into X' plus spokes. domain is X's constrained Delaunay triangulation with its
// exterior and holes removed (vertex ids those of pslg), which says which angles lie inside.
CornerLopping lop_corners(Pslg& pslg, const Mesh& domain);

// Drops the subsegments of the chords and spokes (internal, by input segment index), so that the
// output's segments are X's.
void forget_lopping_edges(Mesh& mesh, const std::vector<char>& internal);

}  // namespace deltri
