// The Voronoi diagram of the mesh (-v), in Triangle's two files.
//   .v.node  <#triangles> 2 <#attributes> 0      then  <index> <x> <y> [<attribute>...]
//            one Voronoi vertex per triangle, numbered as the triangles of the .ele: its
//            circumcentre, with the vertex attributes interpolated linearly there
//   .v.edge  <#edges> 0                          then  <index> <v1> <v2>
//                                                  or  <index> <v1> -1 <dx> <dy>
//            one Voronoi edge per mesh edge, in .edge order: the circumcentres of the two
//            triangles beside it, or for a boundary edge a ray from its triangle's circumcentre
//            in the direction (dx, dy): the edge's outward normal, as long as the edge
// For a constrained or carved mesh these files are the duals of the triangles written, not a true
// Voronoi diagram of the vertices (as in Triangle).
#pragma once

#include <vector>

#include "io/text_writer.h"
#include "mesh/mesh.h"

namespace deltri {

// The Voronoi vertex of live triangle t (its circumcentre) and, into `attributes`, the vertex
// attributes interpolated linearly there.
Point voronoi_vertex(const Mesh& mesh, TriangleId t, std::vector<double>& attributes);

void write_voronoi_node_file(ByteSink& out, const Mesh& mesh, int first_index);
void write_voronoi_edge_file(ByteSink& out, const Mesh& mesh, int first_index);

}  // namespace deltri
