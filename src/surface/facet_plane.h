// Each facet is meshed in coordinates of its own plane: an orthonormal frame (u, v, normal) at the
// facet's centroid, so that lengths, angles and areas in the plane are those in space (to
// rounding) and the 2-D pipeline's -q and -a bounds mean the same in both.
#pragma once

#include "geometry/point.h"
#include "geometry/point3.h"
#include "pslg/facets.h"

namespace deltri {

// Facets may be planar only up to this fraction of their diameter (their points' largest distance
// from the plane, measured along the normal); coordinates written with ten or more significant
// digits pass easily.
inline constexpr double kPlanarTolerance = 1e-6;
// And up to this fraction of their width (the widest triangle's height over the facet's longest
// chord from its first point): a facet whose one far point sets its diameter would otherwise let
// the others lie far off the plane, where their projections may fall on a line and its segments
// overlap in the plane (fuzz finding F13). Ten digits pass on any facet up to 1e6 times longer than wide.
inline constexpr double kWidthTolerance = 1e-3;

struct FacetPlane {
  Point3 origin, u, v, normal;
  double diameter = 0.0;      // of the facet's points (the largest distance from its first point, doubled at most)
  double max_distance = 0.0;  // the farthest point's distance from the plane

  Point to_plane(const Point3& p) const {
    const Point3 d = p - origin;
    return {dot(d, u), dot(d, v)};
  }
  Point3 lift(const Point& q) const { return origin + q.x * u + q.y * v; }
  double distance(const Point3& p) const { return dot(p - origin, normal); }
};

// The plane of facet `f` (0-based): Newell's normal summed over its polygons, through the
// centroid of its points. Throws InputError naming the facet when its points are all collinear
// or when one lies farther than kPlanarTolerance times the facet's diameter, or kWidthTolerance
// times its width, from that plane.
FacetPlane fit_facet_plane(const FacetInput& input, std::size_t f);

}  // namespace deltri
