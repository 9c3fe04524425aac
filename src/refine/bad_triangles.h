// Which triangles Delaunay refinement must split (Fig. 38 l.8, Fig. 39 l.42/l.54): those with an
// angle below theta, unless that angle separates two subsegments (nothing can improve it), and
// those too large for the user (delta(t)).
#pragma once

#include "geometry/mesh_bounds.h"
#include "mesh/mesh.h"
#include "refine/area_field.h"
#include "refine/quality_queue.h"
#include "refine/size_test.h"

namespace deltri {

struct QualityRules {
  AngleBound angle;  // its sin2() is the angle test; 0 turns it off
  SizeBounds size;   // triangle_bounds: also honour mesh.area_bound[t] when positive
  // With bounds that vary within a region (-r with an .area file), the field gives each triangle
  // its bound instead of mesh.area_bound (refine/area_field.h); null or empty: not used.
  const AreaField* area_field = nullptr;
  const SizeTest* size_test = nullptr;  // a caller's test (refine/size_test.h), or null
};

// The area bound that applies to t (<= 0: none), as rules say.
double area_bound_of(const Mesh& mesh, TriangleId t, const QualityRules& rules);

struct TriangleShape {
  EdgeRef shortest = kNone;  // the triangle's shortest edge
  double shortest_length2 = 0.0;
  // (r / B)^2 with r the circumradius-to-shortest-edge ratio and B = 1 / (2 sin theta); > 1 means
  // the smallest angle is below theta. Equals l1^2 l2^2 sin^2(theta) / (2 area)^2 with l1, l2
  // the two other edges, since r = l1 l2 l3 / (4 area).
  double ratio2_over_bound2 = 0.0;
  double area = 0.0;
  double length2[3] = {0.0, 0.0, 0.0};  // squared length of side i (corner i to corner i+1)
};

TriangleShape measure_triangle(const Mesh& mesh, TriangleId t, double sin2_theta);

// The side (0, 1, 2) with the least of the squared lengths len2, the first of tied ones: the edge
// whose Steiner point a triangle gets (measure_triangle, steiner_point_of).
inline unsigned shortest_side(const double len2[3]) {
  unsigned s = 0;
  if (len2[1] < len2[s]) s = 1;
  if (len2[2] < len2[s]) s = 2;
  return s;
}

// The side with the greatest squared length, the first of tied ones.
inline unsigned longest_side(const double len2[3]) {
  unsigned s = 0;
  if (len2[1] > len2[s]) s = 1;
  if (len2[2] > len2[s]) s = 2;
  return s;
}

struct Assessment {
  bool skinny = false;     // smallest angle below theta and not between two subsegments
  bool too_large = false;  // delta(t)
  bool bad() const { return skinny || too_large; }
  TriangleShape shape;
};

// Fig. 38 l.8: "delta(t) or t has an angle less than theta (but not separating two subsegments)".
Assessment assess_triangle(const Mesh& mesh, TriangleId t, const QualityRules& rules);

// How many times its size bounds t exceeds: area over the smallest area bound that applies, or
// (longest edge over the -u edge length) squared; at most 1 when t meets them.
double size_excess(const Mesh& mesh, TriangleId t, const TriangleShape& shape, const QualityRules& rules);

// Whether a queue entry still names a triangle of the mesh: its slot is live and holds the three
// vertices the entry remembers (in any rotation). A slot reused or rewritten by a flip since holds
// other vertices, and the entry is stale (Fig. 38 l.12: "if t still exists").
bool is_current(const Mesh& mesh, const QueuedTriangle& entry);

// sin^2 of the smallest angle of triangle t.
double triangle_sine2(const Mesh& mesh, TriangleId t);

// True when the angle opposite edge e (at apex(e)) lies between two subsegments.
bool angle_between_subsegments(const Mesh& mesh, EdgeRef e);

}  // namespace deltri
