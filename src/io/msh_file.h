// Gmsh MSH (--msh, --msh-format): the whole mesh in one file that Gmsh and solvers read, in
// version 2.2 (the default: what GetDP 3.2 and FreeFem++ read) or 4.1, ASCII or binary.
//   $MeshFormat, $PhysicalNames, $Entities (4.1 only), $Nodes, $Elements, and $NodeData views
//   "marker" and "attribute <k>".
// Nodes are numbered as in the .node written with -z off (1, 2, ...; with -j the kept vertices);
// in 4.1 all of them sit in one node block of surface 1. Triangles (type 2, or 9 with -o2) are
// grouped into one surface per triangle attribute value (one surface "domain" without -A);
// boundary and segment edges (type 1, or 8 with -o2) into one curve per edge marker (none with
// -B). Physical tags follow io/physical_groups.h: positive integer markers keep their number,
// every other group gets a tag above them, and no two groups share a tag; $PhysicalNames says
// which is which ("marker 0", "attribute 2.5", "domain"). Binary files hold the values in the
// machine's byte order, which the header's integer 1 tells readers.
#pragma once

#include "io/output_numbering.h"
#include "io/text_writer.h"
#include "io/physical_groups.h"
#include "mesh/mesh.h"

#include <string>

namespace deltri {

struct MshFormat {
  int version = 22;  // 22 or 41
  bool binary = false;
  long long domain_tag = kDomainTag;  // --domain-tag: the domain's surface tag (the base of -A's tags)
};

// Empty, or which two physical groups format.domain_tag would make share a tag
// ("tag 5 would be both marker 5's and the domain's"): such a file is not to be written.
std::string msh_tag_clash(const Mesh& mesh, const ExportOptions& options, MshFormat format);

void write_msh_file(ByteSink& out, const Mesh& mesh, const ExportOptions& options, MshFormat format = {});

}  // namespace deltri
