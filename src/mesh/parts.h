// Cutting a mesh into parts that are refined apart, and joining them again (refine/halves.h): the
// kernel operations that move triangles between meshes, so that every per-triangle and per-vertex
// array is carried here and in mesh.cpp, and no caller copies a field of Mesh by name.
//
// A cut-off part holds only what it uses: the vertices of its triangles (and any others the
// caller names), and the subsegment records on its edges, renumbered in their order (the part's
// vertex i is CutOff::vertices[i], its record i CutOff::records[i]), so that ids keep their order
// and the part is refined exactly as it would be with the mesh's ids. What it adds while it is
// refined apart (vertices from v0 on, records from s0 on) is numbered after them, and when it is
// appended again its ids are mapped back, its new ones after what the mesh it joins added meanwhile.
#pragma once

#include <cstdint>
#include <vector>

#include "geometry/predicates.h"
#include "mesh/mesh.h"

namespace deltri {

// What cut_off leaves besides the mesh that keeps the other triangles.
struct CutOff {
  Mesh part;                        // the triangles that moved, in slot order from 0
  std::vector<char> part_records;   // by record of the mesh: one of its edges moved and is not on the cut
  std::vector<char> cut_records;    // by record of the mesh: it lies on the cut
  // The cut's edges as org << 32 | dest, oriented as in the mesh that stays, sorted.
  std::vector<std::uint64_t> cut_keys;
  std::vector<VertexId> vertices;     // the mesh's id of each of the part's vertices, increasing
  std::vector<SubsegmentId> records;  // the mesh's id of each of the part's records, increasing
  // The part's id of each of the mesh's `count` vertices, kNone for those it does not hold.
  std::vector<VertexId> vertex_map(std::size_t count) const;
};

// Moves the live triangles t with moves[t] != 0 into a mesh of their own (the vertices they use and
// those with keep[v] != 0, and the records on their edges, copied; the triangle data with each
// triangle; keep may be empty). The edges between the two sides,
// the cut, become boundary edges on both; a cut edge that carries no subsegment is given `mark` on
// both sides (a value above every record id), so that refinement treats it as a constraint. Edges
// already carrying `mark` (an earlier cut's) stay as they are. The moved triangles' slots are freed.
CutOff cut_off(Mesh& mesh, const std::vector<std::uint8_t>& moves, SubsegmentId mark, std::vector<char> keep);

// Where a part's ids land when it is appended: the vertices and records it was cut with (below v0,
// s0) where they were in the mesh; its own vertices (from v0 on) after the mesh's, from vertex_base
// on; its own records (from s0 on) from record_base on; its slots after the mesh's.
struct PartIds {
  const std::vector<VertexId>* vertices = nullptr;  // CutOff::vertices, CutOff::records
  const std::vector<SubsegmentId>* records = nullptr;
  VertexId v0{0}, vertex_base{0};
  SubsegmentId s0{0}, record_base{0};
  TriangleId triangle_base{0};
  VertexId vertex(VertexId v) const {
    return v == kNone ? v : v < v0 ? (*vertices)[v] : VertexId{vertex_base + (v - v0)};
  }
  SubsegmentId record(SubsegmentId s, SubsegmentId mark) const {
    return s == kNone || s == mark ? s : s < s0 ? (*records)[s] : SubsegmentId{record_base + (s - s0)};
  }
  TriangleId triangle(TriangleId t) const { return TriangleId{triangle_base + t}; }
};

// Appends cut.part (refined apart since) to mesh after its own triangles, vertices and records:
// the part's copies of the shared records it owns (part_records) replace the mesh's, its ids are
// mapped back (PartIds), its slots follow the mesh's. The part's arrays are
// freed as they are copied. The cut's edges are still boundary edges afterwards (sew_cut bonds them).
PartIds append_part(Mesh& mesh, CutOff& cut, SubsegmentId mark);

// Bonds the cut's edges of the two sides again and takes `mark` off them; returns them, oriented as
// on the side that stayed, in cut_keys order. Throws std::logic_error when a cut edge has no partner.
std::vector<EdgeRef> sew_cut(Mesh& mesh, const CutOff& cut, const PartIds& ids, SubsegmentId mark);

// Lawson's flips from the edges of `stack` until every edge reached is locally Delaunay; edges that
// carry a subsegment (or any mark) are never flipped. The triangles the flips make go to `touched`.
// For a mesh that is constrained Delaunay except at the given edges (two sides just sewn).
void flip_delaunay_from(Mesh& mesh, Predicates& pred, std::vector<EdgeRef> stack, std::vector<TriangleId>& touched);

}  // namespace deltri
