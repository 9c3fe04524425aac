// Building a triangulation from scratch, for the builders that make triangles themselves (the
// sweepline, -r's rebuild from a .ele): triangles are appended with no twins, then their edges are
// paired. Until every edge that has a twin is paired, the mesh is not valid (mesh.h's invariants
// hold again once the builder is done); nothing here decides geometry beyond what it checks.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>

#include "geometry/predicates.h"
#include "mesh/mesh.h"

namespace deltri {

// Empties the triangles and everything per triangle (links, subsegments, free list, attributes,
// area bounds); the vertices stay.
void clear_triangles(Mesh& mesh);

// Reserves room for `triangles` more triangles' corners and links.
void reserve_triangles(Mesh& mesh, std::size_t triangles);

// A new triangle a, b, c (counter-clockwise) at the end of the arrays, with no twins yet.
TriangleId append_unlinked(Mesh& mesh, VertexId a, VertexId b, VertexId c);

// Makes e and f twins if f runs opposite to e (org(f) == dest(e), dest(f) == org(e)) and has no
// twin yet; otherwise changes nothing and returns false.
bool pair_twins(Mesh& mesh, EdgeRef e, EdgeRef f);

// Why assemble_triangles refused its input: the triangle(s) at fault, in input order.
struct AssemblyProblem {
  enum class Kind {
    None,
    RepeatedVertex,  // first names a vertex twice
    Clockwise,       // first is not strictly counter-clockwise (exact orient2d)
    SharedEdge,      // first has an edge shared by more than two triangles
    Overlap,         // first and second share an edge in the same direction
  };
  Kind kind = Kind::None;
  TriangleId first = kNone, second = kNone;
};

// Replaces the triangles of `mesh` by `count` triangles whose corners are the first three of each
// `stride` entries of `corners`, in order, and pairs their edges by sorting the undirected edge
// keys (no hash table, no per-vertex lists). Edges used once are boundary edges; no edge carries a
// subsegment. Stops at the first
// problem (the mesh is then unusable). Does not check that triangles overlap other than through a
// shared edge (mesh/overlap.h does).
AssemblyProblem assemble_triangles(Mesh& mesh, Predicates& pred, std::span<const std::uint32_t> corners,
                                   std::uint32_t count, std::uint32_t stride);

}  // namespace deltri
