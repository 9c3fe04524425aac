// The .ele format: triangles as corner numbers, counter-clockwise, with optional attributes.
//   <#triangles> [<nodes per triangle 3|6> [<#attributes>]]
//   <index> <n1> <n2> <n3> [<n4> <n5> <n6>] [<attribute>...]
// With six nodes, n4/n5/n6 are the midpoints of the edges opposite n1/n2/n3 (-o2).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "io/file_text.h"
#include "io/text_writer.h"
#include "mesh/mesh.h"
#include "pslg/ele_data.h"

namespace deltri {

// Reads a .ele for -r. `first_index` is the numbering of the matching .node; every node must be
// one of its `vertex_count` vertices. Triangle indices must be integers but are not checked.
// A file of 4 MiB or more is read by two threads when `threads` is 2 or more (--threads).
EleData read_ele_file(const std::string& path, int first_index, std::uint32_t vertex_count, int threads = kReadThreads);

struct EleWriteOptions {
  int first_index = 1;
  // Same meaning as in NodeWriteOptions.
  const std::vector<std::uint32_t>* numbering = nullptr;
  // -o2: three vertex ids per triangle slot, the midpoints of the edges opposite corners 0, 1, 2.
  const std::vector<VertexId>* midpoints = nullptr;
};

// Appends a .ele file: live triangles in slot order, numbered consecutively, with the mesh's
// triangle attributes.
void write_ele_file(std::string& out, const Mesh& mesh, const EleWriteOptions& options);
void write_ele_file(ByteSink& out, const Mesh& mesh, const EleWriteOptions& options);

}  // namespace deltri
