// -r: the triangulation of a previous run, rebuilt from its .ele so that it can be refined again.
//
// The triangles arrive as corner triples. Their edges are paired by sorting the undirected edge
// keys, so no hash table and no per-vertex adjacency lists are needed. What a .ele cannot be
// trusted with is checked, since the file may come from anywhere: every triangle strictly
// counter-clockwise (exact orient2d), and every edge used at most once in each direction, by at
// most two triangles, and no two triangles overlapping or meeting other than at shared corners
// (mesh/overlap.h). Edges used once are the boundary of the mesh; Triangle treats them as
// segments with marker 1 when refining, and so does protect_boundary.
#pragma once

#include <string>
#include <vector>

#include "geometry/predicates.h"
#include "pslg/ele_data.h"
#include "mesh/mesh.h"

namespace deltri {

// Replaces mesh's triangles by those of `ele` (three corners each) and takes its triangle
// attributes. With six nodes per triangle, a vertex named only as a midpoint (nodes 4-6) becomes
// Dead: it is not written, as in Triangle. `ele_path` names the file in errors. Throws InputError.
void rebuild_mesh(Mesh& mesh, Predicates& pred, const EleData& ele, const std::string& ele_path);

// Gives every boundary edge that carries no subsegment yet a subsegment with marker 1.
void protect_boundary(Mesh& mesh);

// Lawson's flips over the whole mesh, never across a subsegment, until every edge is locally
// Delaunay: a mesh written by another program need not be, and refinement assumes it. Needs the
// subsegment array (protect_boundary makes it).
void make_constrained_delaunay(Mesh& mesh, Predicates& pred);

}  // namespace deltri
