// Corner-lopping (Shewchuk 2001, Sec. 6.1, Fig. 22; Bern, Eppstein and Gilbert, Ruppert): the
// input PSLG X becomes X' by shielding each apex a of an input angle under 60 degrees inside the
// domain. The shield is the circle of radius lfs(a)/3 around a (lfs from the nearest feature not
// incident to a: another vertex or a segment without a as an end); a vertex goes where the circle
// meets each segment that bounds such a small angle, and the chord across each small angle (a
// shield edge) becomes a segment. An apex whose small sector has a wider one inside the domain
// next to it is not lopped (see to_be_lopped). The lopped corner is the triangle of a and its chord (its fan, more
// triangles once the chord is split): refinement leaves the triangles inside the small sectors
// alone (RefineOptions::lopped_sectors) and never splits the pieces of segments from a to its
// shield vertices, while it meshes X' around them. Chords are internal: forget_lopping_edges drops
// them before output, whose segments are then those of X, split.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "mesh/mesh.h"
#include "pslg/pslg.h"

namespace deltri {

inline constexpr char kLoppedApex = 1;    // CornerLopping::apex: the centre of a fan
inline constexpr char kShieldVertex = 2;  // a vertex on a shield circle

struct CornerLopping {
  std::vector<char> apex;           // by vertex id: kLoppedApex, kShieldVertex or 0
  std::vector<std::array<VertexId, 3>> sectors;  // apex, shield vertex, next one counter-clockwise; by apex
  std::vector<char> internal;       // by segment index of the changed PSLG: a chord
  std::uint32_t apices = 0;         // how many corners were lopped
  double shortest_radius = 0.0;     // the smallest shield radius, lfs(a)/3 (0 if none)
};

// Changes pslg into X' plus spokes. domain is X's constrained Delaunay triangulation with its
// exterior and holes removed (vertex ids those of pslg), which says which angles lie inside.
CornerLopping lop_corners(Pslg& pslg, const Mesh& domain);

// Drops the subsegments of the chords (internal, by input segment index), so that the
// output's segments are X's.
void forget_lopping_edges(Mesh& mesh, const std::vector<char>& internal);

}  // namespace deltri
