// Finds segments that repeat an earlier one (same two ends, either orientation).
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "mesh/ids.h"

namespace deltri {

// For each segment, the index of the first earlier segment with the same ends, or kNone. Segments
// whose first end is kNone are skipped. Buckets by the smaller end (a counting sort), which is
// linear and far friendlier to the cache than hashing 10^5 pairs.
std::vector<std::uint32_t> find_repeats(const std::vector<std::pair<VertexId, VertexId>>& ends,
                                        std::uint32_t vertex_count);

}  // namespace deltri
