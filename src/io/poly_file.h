// The .poly format: a planar straight line graph.
//   node section        (.node layout; a count of 0 takes the vertices from <base>.node)
//   <#segments> [<#markers 0|1>]        then  <index> <a> <b> [<marker>]
//   <#holes>                            then  <index> <x> <y>
//   [<#regions>                         then  <index> <x> <y> <attribute> [<max area>]]
// Segment, hole and region indices must be integers but are not checked for sequence (Triangle
// ignores them and files in the wild number them loosely). Endpoints are vertex numbers in the
// numbering the first vertex set. A region line without an area uses its attribute as the area,
// as Triangle does.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "io/file_text.h"
#include "io/text_writer.h"
#include "mesh/mesh.h"
#include "pslg/pslg.h"

namespace deltri {

// Reads a .poly file (and its separate .node when its node section is empty); `threads` as for
// read_node_file.
Pslg read_poly_file(const std::string& path, int threads = kReadThreads);

// For each subsegment id, the first live edge carrying it (kNone: gone from the mesh) and
// whether it lies on the mesh boundary: the segments a .poly (and the library) writes, in order.
struct LiveSubsegments {
  std::vector<EdgeRef> edge;
  std::vector<bool> boundary;
  std::uint32_t count = 0;
};
LiveSubsegments find_live_subsegments(const Mesh& mesh);

struct PolyWriteOptions {
  int first_index = 1;
  bool markers = true;  // false: -B
  // Same meaning as in NodeWriteOptions; used for the segment endpoints (and embedded vertices).
  const std::vector<std::uint32_t>* numbering = nullptr;
  // Triangle's output .poly lists no vertices (they are in the .node written next to it); true
  // embeds them, for when no .node is written.
  bool with_vertices = false;
};

// Appends a .poly file: every subsegment still in the mesh, once, in subsegment-id order (input
// segments first, as they were created), then the holes, then the regions if there are any.
// A segment's marker is its subsegment's marker when nonzero, else 1 on the mesh boundary, else 0.
void write_poly_file(std::string& out, const Mesh& mesh, const PolyWriteOptions& options,
                     const std::vector<Point>& holes, const std::vector<Pslg::Region>& regions = {});
void write_poly_file(ByteSink& out, const Mesh& mesh, const PolyWriteOptions& options,
                     const std::vector<Point>& holes, const std::vector<Pslg::Region>& regions = {});

}  // namespace deltri
