// The statistics block in Triangle's labels ("Mesh triangles: 10"), for scripts written against
// Triangle's standard output (--triangle-messages). The figures are deltri's own (MeshStatistics);
// only the labels and the layout of one figure per label follow Triangle.
#pragma once

#include <cstddef>
#include <optional>
#include <string>

#include "quality/statistics.h"

namespace deltri {

struct InputCounts {
  std::size_t vertices = 0;
  std::optional<std::size_t> triangles;  // -r: the triangles of the .ele read
  bool pslg = false;                     // a .poly: segments and holes are reported
  std::size_t segments = 0, holes = 0;
};

// "Input vertices:", "Mesh triangles:", "Mesh exterior boundary edges:" and the rest, one per
// line. The interior boundary edges and subsegments are listed when the mesh has segments.
std::string triangle_counts(const InputCounts& input, const MeshStatistics& mesh, bool has_segments);

// With -V: "Smallest area: ... | Largest area: ...", edges, altitude, aspect ratio, angles and the
// angle histogram in 10-degree bins.
std::string triangle_quality(const MeshStatistics& mesh);

}  // namespace deltri
