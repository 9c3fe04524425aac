// The .node format: vertices with optional attributes and boundary markers.
//   <#vertices> [<dimension = 2> [<#attributes> [<#markers 0|1>]]]
//   <index> <x> <y> [<attribute>...] [<marker>]
// The first vertex's index (0 or 1) sets the numbering of the whole input; later indices should
// follow it consecutively. As in Triangle, indices that do not (and a first index other than 0 or
// 1) are read with a warning, the vertices numbered by their order in the file; where something
// refers to vertices by number this is ambiguous and refused (require_regular_numbering). A
// missing trailing marker is read as 0 with a warning. Fields after the ones the header announces
// are ignored, as Triangle does; so is anything after the last vertex.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "io/line_reader.h"
#include "io/text_writer.h"
#include "mesh/mesh.h"
#include "pslg/pslg.h"

namespace deltri {

// Reads a .node file; at least three vertices are required. A large file is read and parsed by
// two threads when `threads` is 2 or more (--threads), else by the calling thread alone.
Pslg read_node_file(const std::string& path, int threads = kReadThreads);

// Reads a node section (header and vertex lines) into `out`, replacing its vertices; returns the
// header's vertex count, which must be at least 3. With `allow_empty` a count of 0 is accepted
// too: nothing is read and `out` is unchanged (a .poly then takes its vertices from the .node).
std::uint32_t read_node_section(LineReader& in, Pslg& out, bool allow_empty = false);

// Throws the InputError of the first irregular vertex index in `pslg`, if any: `referrer` (e.g.
// "the segments") names vertices by number, and which vertex a number meant is then ambiguous.
void require_regular_numbering(const Pslg& pslg, const std::string& referrer);

struct NodeWriteOptions {
  int first_index = 1;
  bool markers = true;  // false: -B, no marker column
  // nullptr: every vertex in id order. Otherwise numbering[v] is v's output number minus
  // first_index, or kNone to leave v out (-j). Vertices are still written in id order.
  const std::vector<std::uint32_t>* numbering = nullptr;
};

// Appends a .node file of the mesh's vertices; markers come from mesh.marker (0 when empty).
void write_node_file(std::string& out, const Mesh& mesh, const NodeWriteOptions& options);
void write_node_file(ByteSink& out, const Mesh& mesh, const NodeWriteOptions& options);
// The header and vertex lines, for writers that embed a node section.
void write_node_section(TextWriter& out, const Mesh& mesh, const NodeWriteOptions& options);

}  // namespace deltri
