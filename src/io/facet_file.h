// TetGen's facet formats: a piecewise linear complex of planar facets in 3-D.
//
// .poly with a 3-D node section (told from Triangle's .poly by the dimension field, 3):
//   <#points> 3 [<#attributes> [<#markers 0|1>]]     then <index> <x> <y> <z> [attributes] [marker]
//     (a count of 0 takes the points from <base>.node, which has the same layout)
//   <#facets> [<#markers 0|1>]
//   per facet: <#polygons> [<#holes> [<marker>]]     (the marker only when the header says 1)
//     then <#polygons> lines <#corners> <corner 1> ... <corner #corners>
//     then <#holes> lines    <index> <x> <y> <z>
//   then TetGen's volume hole and region sections, which a surface mesh does not use: not read.
// .smesh: the same node section; each facet is one polygon on one line,
//   <#corners> <corner 1> ... <corner #corners> [<marker>]
//
// A polygon of one corner is a vertex in the facet, of two a segment, of three or more a closed
// loop. Corners must be vertex numbers in the numbering the first vertex set.
#pragma once

#include <string>

#include "io/file_text.h"
#include "pslg/facets.h"

namespace deltri {

// Whether `path` holds TetGen facets: a .smesh, or a file whose node header's dimension is 3.
// False when the file cannot be read (the ordinary reader then says why).
bool is_facet_file(const std::string& path);

// Throws InputError "file:line: what is wrong" on any malformed or inconsistent content. A file
// of 4 MiB or more is read by two threads when `threads` is 2 or more (--threads).
FacetInput read_facet_file(const std::string& path, int threads = kReadThreads);

}  // namespace deltri
