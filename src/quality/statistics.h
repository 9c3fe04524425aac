// Mesh counts and shape measures for the summary and the -V report. Plain floating point: these are
// figures for people, not decisions, so nothing here needs exact arithmetic.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>

#include "mesh/mesh.h"

namespace deltri {

// Upper bounds of the aspect-ratio bins; bin i holds ratios in [bound[i-1], bound[i]), the last
// bin everything from 100000 up (including flat triangles, whose ratio is infinite).
inline constexpr std::array<double, 15> kAspectBinBounds = {
    1.5, 2.0, 2.5, 3.0, 4.0, 6.0, 10.0, 15.0, 25.0, 50.0, 100.0, 300.0, 1000.0, 10000.0, 100000.0};
inline constexpr std::size_t kAspectBins = kAspectBinBounds.size() + 1;

struct MeshStatistics {
  // Counts.
  std::uint32_t vertices = 0;               // vertices not of kind Duplicate or Dead
  std::uint32_t vertices_in_triangles = 0;  // vertices that are a corner of some triangle
  std::uint32_t triangles = 0;
  std::uint64_t edges = 0;
  // Edges with a triangle on one side only (convex hull or hole boundary).
  std::uint64_t exterior_boundary_edges = 0;
  // Subsegment edges with triangles on both sides.
  std::uint64_t interior_boundary_edges = 0;
  std::uint64_t subsegments = 0;  // edges carrying a subsegment

  // Shape measures over all live triangles; all zero when there are none.
  double smallest_area = 0.0, largest_area = 0.0;
  double shortest_edge = 0.0, longest_edge = 0.0;
  double shortest_altitude = 0.0;
  // Of one triangle: its longest edge over its shortest altitude (2 / sqrt(3) when equilateral);
  // infinite for a flat triangle.
  double largest_aspect_ratio = 0.0;
  double smallest_angle = 0.0, largest_angle = 0.0;  // degrees

  // Every angle of every triangle is counted (three per triangle). A bin holds angles in
  // [lower, lower + width), except that 180 degrees falls in the last bin.
  std::array<std::uint64_t, 18> angle_histogram{};       // 10-degree bins over 0-180
  std::array<std::uint64_t, 180> angle_histogram_fine{};  // 1-degree bins over 0-180
  std::array<std::uint64_t, kAspectBins> aspect_histogram{};  // one count per triangle
  // The same bins closed above, (bound[i-1], bound[i]], as Triangle's -V counts them: an isosceles
  // right triangle (ratio exactly 2) is in 1.5 - 2 here, in 2 - 2.5 above.
  std::array<std::uint64_t, kAspectBins> aspect_histogram_triangle{};
};

// Expects a mesh whose storage is sound (check_mesh finds no storage faults); orientation and
// links may be wrong, areas and angles are taken unsigned.
MeshStatistics compute_statistics(const Mesh& mesh);

// A multi-line block for the -V report, each line ending in '\n'.
std::string format_statistics(const MeshStatistics& stats);

}  // namespace deltri
