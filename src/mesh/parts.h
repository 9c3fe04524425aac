// Cutting a mesh into parts that are refined apart, and joining them again (refine/refine_in_parts.h): the
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

// What the side that stays holds while the part cut off is refined apart (hold_only): like the
// part, only the vertices of its triangles (and any others the caller names) and the records on
// their edges, renumbered in their order, so that it is refined exactly as with the mesh's ids;
// its triangle slots stay where they are. What neither side holds waits here, in the mesh's ids,
// until hold_all gives the mesh back its ids.
struct Held {
  std::vector<VertexId> vertices;     // the mesh's id of each vertex the side holds, increasing
  std::vector<SubsegmentId> records;  // the mesh's id of each record the side holds, increasing
  VertexId whole_vertices{0};         // the mesh's counts at the cut
  SubsegmentId whole_records{0};
  std::vector<VertexId> rest_vertices;     // held by neither side, increasing
  std::vector<SubsegmentId> rest_records;  // held by neither side, increasing
  Mesh rest;  // their vertex data and records (endpoints in the mesh's ids), in that order
  // The mesh's id of the side's vertex v or record s (those it added come after the mesh's).
  VertexId whole_vertex(VertexId v) const {
    return v == kNone ? v : v < vertices.size() ? vertices[v] : VertexId{whole_vertices + (v - static_cast<std::uint32_t>(vertices.size()))};
  }
  SubsegmentId whole_record(SubsegmentId s) const {
    return s < records.size() ? records[s] : SubsegmentId{whole_records + (s - static_cast<std::uint32_t>(records.size()))};
  }
};

// Renumbers the mesh left by cut_off to what its triangles use (and the vertices with keep[v] != 0),
// in place: the per-vertex and per-record arrays shrink and give the pages of their tails back,
// corners and subsegments take the new ids (a mark above every record id stays), and what
// neither this side nor cut.part holds is kept in Held::rest. With `threads` 2 or more, two
// threads share the renumbering.
Held hold_only(Mesh& mesh, const CutOff& cut, std::vector<char> keep, int threads = 1);

// Gives the mesh its ids of before hold_only back, in place, with what it added since numbered
// after them (vertices from Held::whole_vertices on, records from Held::whole_records on): the
// vertices only cut.part holds come from it, unchanged since the cut; the records only it holds
// are left to append_part, which writes every record the part owns. With `threads` 2 or more, two
// threads share the renumbering.
void hold_all(Mesh& mesh, Held& held, const CutOff& cut, int threads = 1);

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
// With `threads` 2 or more, two threads share the copying.
PartIds append_part(Mesh& mesh, CutOff& cut, SubsegmentId mark, int threads = 2);

// Bonds the cut's edges of the two sides again and takes `mark` off them; returns them, oriented as
// on the side that stayed, in cut_keys order. Throws std::logic_error when a cut edge has no partner.
// With `threads` 2 or more, two threads search the slots.
std::vector<EdgeRef> sew_cut(Mesh& mesh, const CutOff& cut, const PartIds& ids, SubsegmentId mark, int threads = 1);

// Lawson's flips from the edges of `stack` until every edge reached is locally Delaunay; edges that
// carry a subsegment (or any mark) are never flipped. The triangles the flips make go to `touched`.
// For a mesh that is constrained Delaunay except at the given edges (two sides just sewn).
void flip_delaunay_from(Mesh& mesh, Predicates& pred, std::vector<EdgeRef> stack, std::vector<TriangleId>& touched);

}  // namespace deltri
