#include "quality/statistics.h"

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <limits>
#include <vector>

#include "geometry/constructions.h"
#include "refine/criteria.h"  // angle_degrees: the angles the bounds are measured by

namespace deltri {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// The measures of one triangle that the mesh-wide figures are made of.
struct TriangleShape {
  double cross = 0.0;                   // twice the area
  std::array<double, 3> squared_edge{};  // side i runs from corner i to corner i+1
  std::array<double, 3> angle{};         // degrees, at corner i
};

TriangleShape shape_of(const Mesh& mesh, TriangleId t) {
  const auto [p0, p1, p2] = mesh.corner_points(t);
  TriangleShape s;
  s.cross = std::fabs((p1.x - p0.x) * (p2.y - p0.y) - (p1.y - p0.y) * (p2.x - p0.x));
  s.squared_edge = {squared_distance(p0, p1), squared_distance(p1, p2), squared_distance(p2, p0)};
  s.angle = {angle_degrees(p0, p1, p2), angle_degrees(p1, p2, p0), angle_degrees(p2, p0, p1)};
  return s;
}

std::size_t aspect_bin(double ratio) {
  const auto above = std::upper_bound(kAspectBinBounds.begin(), kAspectBinBounds.end(), ratio);
  return static_cast<std::size_t>(above - kAspectBinBounds.begin());
}

template <std::size_t N>
std::size_t angle_bin(double degrees, double width) {
  const double bin = std::floor(degrees / width);
  if (!(bin >= 0.0)) return 0;
  return std::min(static_cast<std::size_t>(bin), N - 1);
}

// Running minima and maxima; squared lengths until the end so that sqrt runs twice, not 6M times.
struct Extremes {
  double min_cross = kInfinity, max_cross = 0.0;
  double min_sq_edge = kInfinity, max_sq_edge = 0.0;
  double min_altitude = kInfinity, max_aspect = 0.0;
  double min_angle = kInfinity, max_angle = 0.0;
};

void add_shape(const TriangleShape& s, Extremes& x, MeshStatistics& stats) {
  const auto [lo, hi] = std::minmax_element(s.squared_edge.begin(), s.squared_edge.end());
  const double longest = std::sqrt(*hi);
  const double aspect = s.cross > 0.0 ? *hi / s.cross : kInfinity;  // longest / (cross / longest)
  x.min_cross = std::min(x.min_cross, s.cross);
  x.max_cross = std::max(x.max_cross, s.cross);
  x.min_sq_edge = std::min(x.min_sq_edge, *lo);
  x.max_sq_edge = std::max(x.max_sq_edge, *hi);
  if (longest > 0.0) x.min_altitude = std::min(x.min_altitude, s.cross / longest);
  x.max_aspect = std::max(x.max_aspect, aspect);
  ++stats.aspect_histogram[aspect_bin(aspect)];
  ++stats.aspect_histogram_triangle[static_cast<std::size_t>(
      std::lower_bound(kAspectBinBounds.begin(), kAspectBinBounds.end(), aspect) - kAspectBinBounds.begin())];
  for (const double a : s.angle) {
    x.min_angle = std::min(x.min_angle, a);
    x.max_angle = std::max(x.max_angle, a);
    ++stats.angle_histogram[angle_bin<18>(a, 10.0)];
    ++stats.angle_histogram_fine[angle_bin<180>(a, 1.0)];
  }
}

void store_extremes(const Extremes& x, MeshStatistics& stats) {
  stats.smallest_area = x.min_cross / 2.0;
  stats.largest_area = x.max_cross / 2.0;
  stats.shortest_edge = std::sqrt(x.min_sq_edge);
  stats.longest_edge = std::sqrt(x.max_sq_edge);
  stats.shortest_altitude = x.min_altitude == kInfinity ? 0.0 : x.min_altitude;
  stats.largest_aspect_ratio = x.max_aspect;
  stats.smallest_angle = x.min_angle;
  stats.largest_angle = x.max_angle;
}

void count_vertices(const Mesh& mesh, MeshStatistics& stats) {
  std::vector<std::uint8_t> in_triangle(mesh.vertex_count(), 0);
  for (TriangleId t{0}; t < mesh.triangle_slots(); ++t)
    if (mesh.is_live(t))
      for (unsigned i = 0; i < 3; ++i) in_triangle[mesh.corner[edge_of(t, i)]] = 1;
  for (VertexId v{0}; v < mesh.vertex_count(); ++v) {
    const VertexKind k = mesh.kind[v];
    if (k != VertexKind::Duplicate && k != VertexKind::Dead) ++stats.vertices;
    stats.vertices_in_triangles += in_triangle[v];
  }
}

// Each undirected edge is counted once: from its smaller twin, or from itself on the boundary.
void count_edges(const Mesh& mesh, MeshStatistics& stats) {
  for (EdgeRef e{0}; e < mesh.corner.size(); ++e) {
    if (!mesh.is_live(triangle_of(e))) continue;
    const EdgeRef f = mesh.link[e];
    if (f != kNone && f < e) continue;
    const bool constrained = mesh.has_subsegments() && mesh.subseg.has(e);
    ++stats.edges;
    stats.subsegments += constrained;
    if (f == kNone)
      ++stats.exterior_boundary_edges;
    else
      stats.interior_boundary_edges += constrained;
  }
}

__attribute__((format(printf, 1, 2))) std::string printf_string(const char* fmt, ...) {
  char buffer[256];
  va_list args;
  va_start(args, fmt);
  std::vsnprintf(buffer, sizeof buffer, fmt, args);
  va_end(args);
  return buffer;
}

std::string aspect_label(std::size_t bin) {
  if (bin == 0) return printf_string("< %g", kAspectBinBounds[0]);
  if (bin == kAspectBins - 1) return printf_string(">= %g", kAspectBinBounds[bin - 1]);
  return printf_string("%g - %g", kAspectBinBounds[bin - 1], kAspectBinBounds[bin]);
}

std::string angle_label(std::size_t bin) { return printf_string("%zu - %zu", 10 * bin, 10 * bin + 10); }

// Two columns: the first half of the bins on the left, the second half on the right.
template <std::size_t N, class Label>
std::string two_columns(const std::array<std::uint64_t, N>& counts, Label label) {
  std::string out;
  const std::size_t half = (N + 1) / 2;
  for (std::size_t i = 0; i < half; ++i) {
    out += printf_string("    %14s: %-12llu", label(i).c_str(), static_cast<unsigned long long>(counts[i]));
    if (i + half < N)
      out += printf_string("  %14s: %llu", label(i + half).c_str(),
                    static_cast<unsigned long long>(counts[i + half]));
    out += "\n";
  }
  return out;
}

std::string format_counts(const MeshStatistics& s) {
  std::string out;
  out += printf_string("  Mesh vertices: %u (%u in triangles)\n", s.vertices, s.vertices_in_triangles);
  out += printf_string("  Mesh triangles: %u\n", s.triangles);
  out += printf_string("  Mesh edges: %llu\n", static_cast<unsigned long long>(s.edges));
  out += printf_string("  Boundary edges: %llu exterior, %llu interior\n",
                static_cast<unsigned long long>(s.exterior_boundary_edges),
                static_cast<unsigned long long>(s.interior_boundary_edges));
  out += printf_string("  Subsegments (constrained edges): %llu\n",
                static_cast<unsigned long long>(s.subsegments));
  return out;
}

std::string format_shapes(const MeshStatistics& s) {
  std::string out;
  out += printf_string("  Area:     smallest %-14.6g largest %.6g\n", s.smallest_area, s.largest_area);
  out += printf_string("  Edge:     shortest %-14.6g longest %.6g\n", s.shortest_edge, s.longest_edge);
  out += printf_string("  Altitude: shortest %.6g\n", s.shortest_altitude);
  out += printf_string("  Aspect ratio (longest edge / shortest altitude): largest %.6g\n",
                s.largest_aspect_ratio);
  out += printf_string("  Angle:    smallest %-14.6g largest %.6g (degrees)\n", s.smallest_angle,
                s.largest_angle);
  out += "  Aspect ratio histogram (triangles):\n";
  out += two_columns(s.aspect_histogram, aspect_label);
  out += "  Angle histogram (degrees; every angle of every triangle):\n";
  out += two_columns(s.angle_histogram, angle_label);
  return out;
}

}  // namespace

MeshStatistics compute_statistics(const Mesh& mesh) {
  MeshStatistics stats;
  count_vertices(mesh, stats);
  count_edges(mesh, stats);
  Extremes extremes;
  for (TriangleId t{0}; t < mesh.triangle_slots(); ++t) {
    if (!mesh.is_live(t)) continue;
    ++stats.triangles;
    add_shape(shape_of(mesh, t), extremes, stats);
  }
  if (stats.triangles > 0) store_extremes(extremes, stats);
  return stats;
}

std::string format_statistics(const MeshStatistics& stats) {
  std::string out = format_counts(stats);
  if (stats.triangles == 0) return out + "  No triangles, so no shape statistics.\n";
  return out + format_shapes(stats);
}

}  // namespace deltri
