// The .edge format (-e): every edge of the mesh once.
//   <#edges> <#markers 0|1>
//   <index> <a> <b> [<marker>]
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "io/text_writer.h"
#include "mesh/mesh.h"

namespace deltri {

struct EdgeWriteOptions {
  int first_index = 1;
  bool markers = true;  // false: -B
  // Same meaning as in NodeWriteOptions.
  const std::vector<std::uint32_t>* numbering = nullptr;
};

// The number of edges of the mesh (each once).
std::uint32_t count_edges(const Mesh& mesh);

// Appends a .edge file. Live triangles are visited in slot order, sides 0, 1, 2; an edge is
// written from the triangle with the smaller slot (as Triangle writes it from the triangle with
// the smaller pool position), or from its only triangle on the boundary, running org -> dest of
// that triangle's side. Marker: the subsegment's marker when the edge carries one that is
// nonzero, else 1 on the mesh boundary, else 0.
void write_edge_file(std::string& out, const Mesh& mesh, const EdgeWriteOptions& options);
void write_edge_file(ByteSink& out, const Mesh& mesh, const EdgeWriteOptions& options);

}  // namespace deltri
