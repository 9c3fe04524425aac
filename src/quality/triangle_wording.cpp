#include "quality/triangle_wording.h"

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
  out += count_line("Mesh vertices", s.vertices);
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
