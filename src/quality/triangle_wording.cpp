#include "quality/triangle_wording.h"

#include <cmath>
#include <cstdio>

namespace deltri {
namespace {

std::string count_line(const char* label, unsigned long long n) {
  char buffer[96];
  std::snprintf(buffer, sizeof buffer, "  %s: %llu\n", label, n);
  return buffer;
}

// Two labelled figures side by side, as Triangle lays out its quality statistics.
std::string pair_line(const char* left, double a, const char* right, double b) {
  char buffer[160];
  std::snprintf(buffer, sizeof buffer, "  %-18s %14.5g   |  %-21s %14.5g\n", left, a, right, b);
  return buffer;
}

// The ratio bins in two columns, as Triangle's -V lays them out; the first bin starts at the
// equilateral triangle's ratio, 2 / sqrt(3).
std::string aspect_histogram(const MeshStatistics& s) {
  std::string out = "\n  Triangle aspect ratio histogram:\n";
  const std::size_t half = kAspectBins / 2;
  const auto bound = [](std::size_t bin) { return bin == 0 ? 2.0 / std::sqrt(3.0) : kAspectBinBounds[bin - 1]; };
  for (std::size_t i = 0; i < half; ++i) {
    const std::size_t j = i + half;
    char upper[16] = "";
    if (j < kAspectBinBounds.size()) std::snprintf(upper, sizeof upper, "%g", kAspectBinBounds[j]);
    char buffer[160];
    std::snprintf(buffer, sizeof buffer, "  %6g - %-6g    :  %8llu    | %6g - %-6s     :  %8llu\n", bound(i),
                  kAspectBinBounds[i], static_cast<unsigned long long>(s.aspect_histogram_triangle[i]), bound(j), upper,
                  static_cast<unsigned long long>(s.aspect_histogram_triangle[j]));
    out += buffer;
  }
  return out + "  (Aspect ratio is longest edge divided by shortest altitude)\n\n";
}

}  // namespace

std::string triangle_counts(const InputCounts& in, const MeshStatistics& s, bool has_segments) {
  std::string out = "\nStatistics:\n\n";
  out += count_line("Input vertices", in.vertices);
  if (in.triangles) out += count_line("Input triangles", *in.triangles);
  if (in.pslg) {
    out += count_line("Input segments", in.segments);
    out += count_line("Input holes", in.holes);
  }
  out += "\n";
  out += count_line("Mesh vertices", s.vertices_in_triangles);  // as Triangle: not the unused ones
  out += count_line("Mesh triangles", s.triangles);
  out += count_line("Mesh edges", s.edges);
  out += count_line("Mesh exterior boundary edges", s.exterior_boundary_edges);
  if (has_segments) {
    out += count_line("Mesh interior boundary edges", s.interior_boundary_edges);
    out += count_line("Mesh subsegments (constrained edges)", s.subsegments);
  }
  return out;
}

std::string triangle_quality(const MeshStatistics& s) {
  std::string out = "\nMesh quality statistics:\n\n";
  if (s.triangles == 0) return out + "  No triangles.\n";
  out += pair_line("Smallest area:", s.smallest_area, "Largest area:", s.largest_area);
  out += pair_line("Shortest edge:", s.shortest_edge, "Longest edge:", s.longest_edge);
  out += pair_line("Shortest altitude:", s.shortest_altitude, "Largest aspect ratio:", s.largest_aspect_ratio);
  out += aspect_histogram(s);
  out += pair_line("Smallest angle:", s.smallest_angle, "Largest angle:", s.largest_angle);
  out += "\n  Angle histogram:\n";
  const std::size_t half = s.angle_histogram.size() / 2;
  for (std::size_t i = 0; i < half; ++i) {
    char buffer[128];
    std::snprintf(buffer, sizeof buffer, "    %3zu - %3zu degrees: %8llu    |  %3zu - %3zu degrees: %8llu\n", 10 * i,
                  10 * i + 10, static_cast<unsigned long long>(s.angle_histogram[i]), 10 * (i + half),
                  10 * (i + half) + 10, static_cast<unsigned long long>(s.angle_histogram[i + half]));
    out += buffer;
  }
  return out;
}

}  // namespace deltri
