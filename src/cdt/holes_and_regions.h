// The constrained Delaunay stage, part two: removes what lies outside the domain (concavities and
// holes) and spreads regional attributes and area bounds. Both flood across edges that carry no
// subsegment ("virus" spreading in Triangle's terms).
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "geometry/predicates.h"
#include "mesh/mesh.h"
#include "pslg/pslg.h"

namespace deltri {

struct HoleReport {
  std::vector<std::size_t> outside;     // indices of hole points outside the triangulation (ignored)
  std::vector<std::size_t> on_segment;  // indices of hole points exactly on a subsegment or on a
                                        // segment's vertex, where the side is ambiguous (ignored)
  std::size_t triangles_removed = 0;
  std::size_t subsegments_removed = 0;  // subsegments left with no triangle on either side
};

// Unless keep_convex_hull, every triangle reachable from a boundary edge without a subsegment is
// exterior; so is every triangle containing a hole point. Exterior triangles are flooded across
// edges without subsegments and deleted. Subsegments with no triangle left on either side are
// deleted from mesh.subsegments (the survivors keep their order and are renumbered). Finally the
// triangles are compacted, so triangle ids change.
// A hole point on a subsegment whose input segment (input_segments, indexed as the subsegments'
// `segment`) does not pass through it lies there only because snapping bent the segment's chain
// through a vertex an ulp or so off it: the point takes the side the input segment puts it on.
HoleReport carve_holes(Mesh& mesh, Predicates& pred, const std::vector<Point>& holes, bool keep_convex_hull,
                       std::span<const Pslg::Segment> input_segments = {});

struct RegionReport {
  std::vector<std::size_t> outside;     // indices of region points outside the mesh (ignored)
  std::vector<std::size_t> on_segment;  // indices of region points exactly on a subsegment or on a
                                        // vertex a subsegment ends at (ignored, as hole points are)
};

// Floods from the triangle containing each region point up to subsegments, in input order, so a
// later region overrides an earlier one where they cover the same triangles (as Triangle does).
// With `attributes`, adds one triangle attribute, the last one: the region's attribute, 0 outside
// every region. With `area_bounds`, fills mesh.area_bound (one per triangle; -1 = no bound) with
// the region's maximum area, a negative one included. A region point outside the mesh is
// ignored, and so is one exactly on a segment or on a vertex a segment ends at, where the side is
// ambiguous: the same rule as for hole points, for the CLI and any other caller of this function.
// A point on an edge or vertex without a segment is fine: every triangle there is in one region.
// A point on a subsegment that snapping bent through it takes its input segment's side, as a hole
// point does (carve_holes).
RegionReport spread_regions(Mesh& mesh, Predicates& pred, const std::vector<Pslg::Region>& regions,
                    bool attributes, bool area_bounds, std::span<const Pslg::Segment> input_segments = {});

}  // namespace deltri
