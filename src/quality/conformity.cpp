#include "quality/conformity.h"

#include <algorithm>
#include <cfloat>
#include <cmath>

#include "geometry/constructions.h"
#include "geometry/predicates.h"
#include "quality/bound_misses.h"

namespace deltri {
namespace {

// Whether subsegment edge e (a triangle on both sides) is beyond what doubles can split: it is at
// most kPrecisionUlps ulps long, or its rounded midpoint would make a triangle with one of the two
// apices clockwise or flat (an apex flush with its line, as where nearly collinear input segments
// were repaired): the tests refinement locks a subsegment by (refine/terminator_policies.cpp).
bool at_precision_limit(const Mesh& m, Predicates& pred, EdgeRef e) {
  const Point& a = m.point(m.org(e));
  const Point& b = m.point(m.dest(e));
  const double largest = std::max({std::fabs(a.x), std::fabs(a.y), std::fabs(b.x), std::fabs(b.y), DBL_MIN});
  if (std::hypot(b.x - a.x, b.y - a.y) <= kPrecisionUlps * (std::nextafter(largest, INFINITY) - largest)) return true;
  const Point mid = midpoint(a, b);
  for (const EdgeRef side : {e, m.link[e]}) {
    const Point& o = m.point(m.org(side));
    const Point& d = m.point(m.dest(side));
    const Point& c = m.point(m.apex(side));
    if (pred.orient2d(o, mid, c) <= 0.0 || pred.orient2d(mid, d, c) <= 0.0) return true;
  }
  return false;
}

}  // namespace

ConformityMisses count_conformity_misses(const Mesh& mesh) {
  ConformityMisses misses;
  if (!mesh.has_subsegments()) return misses;
  Predicates pred;
  for (EdgeRef e{0}; e < mesh.corner.size(); ++e) {
    if (!mesh.is_live(triangle_of(e)) || !mesh.subseg.has(e)) continue;
    const EdgeRef f = mesh.link[e];
    if (f == kNone || f < e) continue;
    const Point& a = mesh.point(mesh.org(e));
    const Point& b = mesh.point(mesh.dest(e));
    if (pred.incircle(a, b, mesh.point(mesh.apex(e)), mesh.point(mesh.apex(f))) <= 0.0) continue;
    ++misses.total;
    misses.double_precision += at_precision_limit(mesh, pred, e);
  }
  return misses;
}

}  // namespace deltri
