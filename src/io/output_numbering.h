// How mesh ids become the numbers written in output files. Shared by every writer so that .node,
// .ele, .poly, .edge and .neigh always agree.
#pragma once

#include <cstdint>
#include <vector>

#include "io/text_writer.h"
#include "mesh/mesh.h"

namespace deltri {

// Vertex v is written as first_index + v, or, when a map is given (-j), as first_index + map[v];
// map[v] == kNone means v is not written at all.
struct VertexNumbering {
  const std::vector<std::uint32_t>* map = nullptr;
  int first_index = 1;

  bool written(VertexId v) const { return map == nullptr || (*map)[v] != kNone; }
  std::uint32_t written_count(std::uint32_t vertex_count) const {
    std::uint32_t n = 0;
    for (VertexId v{0}; v < vertex_count; ++v) n += written(v);
    return n;
  }
  long long operator()(VertexId v) const {
    return static_cast<long long>(map ? (*map)[v] : v) + first_index;
  }
};

// Live triangles are numbered consecutively in slot order (dead slots are skipped), from 0.
// Empty result means "slot t is number t" (no dead slots), to save the array in the common case.
std::vector<std::uint32_t> number_live_triangles(const Mesh& mesh);

// An edge shared by two triangles is written once, from the triangle with the smaller slot (its
// twin lies in another triangle, so comparing edge refs compares slots); a boundary edge always.
inline bool edge_written_here(const Mesh& mesh, EdgeRef e) { return mesh.link[e] == kNone || mesh.link[e] > e; }

// The marker every output gives an edge: its subsegment's marker when non-zero, else 1 on the mesh
// boundary, else 0 (Triangle's rule, shared by .edge, -o2 midpoints, .msh and .vtu).
int edge_marker(const Mesh& mesh, EdgeRef e);

// The edges single-file formats write as line elements: those on the mesh boundary or on a
// segment, each once, in .edge order.
std::vector<EdgeRef> boundary_and_segment_edges(const Mesh& mesh);

// What the single-file formats (.msh, .vtu, .svg) are given besides the mesh.
struct ExportOptions {
  const std::vector<std::uint32_t>* numbering = nullptr;  // as in NodeWriteOptions
  const std::vector<VertexId>* midpoints = nullptr;        // -o2: see add_edge_midpoints
  bool markers = true;                                      // false: -B
};

// The written vertices as "x y 0" lines in id order: the 3-D points of the single-file formats.
void write_points_xyz(TextWriter& out, const Mesh& mesh, const VertexNumbering& number);

inline std::uint32_t triangle_number(const std::vector<std::uint32_t>& numbers, TriangleId t) {
  return numbers.empty() ? t : numbers[t];
}

}  // namespace deltri
