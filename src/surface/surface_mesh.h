// A triangulated surface in 3-D: the result of meshing adjoining planar facets (surface_mesher.h).
// Plain data for the writers and the -C check.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "geometry/point3.h"
#include "mesh/mesh.h"
#include "surface/facet_plane.h"

namespace deltri {

struct SurfaceMesh {
  struct Edge {
    std::uint32_t a = 0, b = 0;
    std::uint32_t segment = 0;  // the input segment (surface_segments.h) it is part of
  };

  // Vertices: the input's points first (ids as in the file, 0-based), then the split points of
  // shared segments, then each facet's own new vertices.
  std::vector<Point3> points;
  bool has_markers = false;
  std::vector<int> markers;                  // one per point when has_markers (0 for new ones)
  std::vector<std::array<std::uint32_t, 3>> triangles;  // the vertex ids of each triangle
  std::vector<std::uint32_t> triangle_facet; // the facet (0-based) each triangle belongs to
  std::vector<Edge> subsegments;             // every piece of every input segment, once
  std::vector<int> facet_marker;             // per facet

  // Kept for -C, which checks each facet exactly in its own plane coordinates.
  std::vector<FacetPlane> planes;
  std::vector<Mesh> facet_meshes;                       // per facet, in plane coordinates
  std::vector<std::vector<std::uint32_t>> facet_vertex; // per facet: its mesh's vertex -> points id
  std::vector<std::vector<std::uint32_t>> segment_facets;  // per input segment: the facets holding it

  std::size_t triangle_count() const { return triangle_facet.size(); }
  // A subsegment's marker (.edge, the library's edge markers): that of the first facet holding its segment.
  int subsegment_marker(std::size_t s) const { return facet_marker[segment_facets[subsegments[s].segment].front()]; }
};

}  // namespace deltri
