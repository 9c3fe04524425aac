// -C for a surface mesh (surface_mesher.h), in layers:
//   each facet   the 2-D check of its mesh in plane coordinates (quality/check_mesh.h, exact), and
//                every boundary edge of it on an input segment: with no overlaps, the facet's
//                domain is covered exactly once
//   conforming   every facet holding an input segment has the same pieces of it (the same pairs
//                of vertices in space) as subsegments: a shared subsegment is an edge of a
//                triangle in every facet that holds it
//   planar       every triangle's corners within kPlanarTolerance of its facet's diameter from
//                the facet's plane, and no triangle of zero area in space
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "surface/surface_mesh.h"

namespace deltri {

struct SurfaceCheck {
  std::uint64_t faults = 0;
  std::vector<std::string> examples;  // the first few faults, one line each
  bool ok() const { return faults == 0; }
  std::string summary() const;
  // The count and the first fault on one line, for the refusal without -C.
  std::string one_line() const;
};

SurfaceCheck check_surface(const SurfaceMesh& mesh);

}  // namespace deltri
