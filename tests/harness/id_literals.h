// Literal ids for tests: 3_v is VertexId{3}, 4_t TriangleId{4}, 5_e EdgeRef{5}, 0_s
// SubsegmentId{0}. The program makes ids only explicitly (src/mesh/ids.h); tests name small
// meshes by their numbers, and a suffix keeps the kind visible.
#pragma once

#include <cstdint>

#include "mesh/ids.h"

namespace deltri {

constexpr VertexId operator""_v(unsigned long long n) { return VertexId{static_cast<std::uint32_t>(n)}; }
constexpr TriangleId operator""_t(unsigned long long n) { return TriangleId{static_cast<std::uint32_t>(n)}; }
constexpr EdgeRef operator""_e(unsigned long long n) { return EdgeRef{static_cast<std::uint32_t>(n)}; }
constexpr SubsegmentId operator""_s(unsigned long long n) { return SubsegmentId{static_cast<std::uint32_t>(n)}; }

}  // namespace deltri
