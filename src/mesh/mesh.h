// The triangulation: flat arrays indexed by 32-bit ids, no per-triangle objects.
//
// Each triangle t owns three consecutive slots 3t, 3t+1, 3t+2, one per corner and one per edge.
// Slot e = 3t+i names corner i and the oriented edge from corner i to corner i+1; the triangle lies
// on the left of each of its edges, so the corners are counter-clockwise.
//
/*
                        apex = corner[lprev(e)]
                            /\
              lprev(e)     /  \     lnext(e)
                          /    \
                         /  t   \
                        /________\
           org = corner[e]   e    dest = corner[lnext(e)]
                        ----------
                          sym(e) = link[e]   (the same edge, reversed, in the neighbour)
*/
//
//   corner[e]  the vertex at the origin of edge e (so corner[3t..3t+2] are t's vertices)
//   link[e]    the oriented edge of the neighbouring triangle that shares edge e, running the other
//              way, or kNone where e is on the boundary of the mesh
//   subseg[e]  the subsegment lying on edge e, or kNone (empty until segments exist); sparse
//              (mesh/subsegment_slots.h): a bit per slot, subseg.has(e), and a hash table of the
//              ids of the few slots that carry one (a dense array where many do)
//
// Guibas-Stolfi navigation follows from these two arrays alone:
//   org(e) = corner[e], dest(e) = corner[lnext(e)], apex(e) = corner[lprev(e)], sym(e) = link[e],
//   onext(e) = sym(lprev(e))   the next edge counter-clockwise around org(e)
//   oprev(e) = lnext(sym(e))   the next edge clockwise around org(e)
// and .neigh's "neighbour opposite corner i" is the triangle of link[3t + (i+1)%3].
//
// Invariants (checked by quality/check_mesh):
//   * every live triangle has three distinct vertices in strictly counter-clockwise order;
//   * link is an involution: link[link[e]] == e, and the two edges have swapped endpoints;
//   * subseg[e] == subseg[link[e]] whenever both edges exist;
//   * a dead triangle has corner[3t] == kNone and sits on the free list.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "geometry/point.h"
#include "mesh/ids.h"
#include "mesh/subsegment_slots.h"
#include "util/big_allocator.h"

namespace deltri {

// Why a vertex exists; decides what refinement may do with it and what the output says.
enum class VertexKind : std::uint8_t {
  Input,      // from the input file
  Duplicate,  // an input vertex at the same place as an earlier one; used by no triangle
  Segment,    // inserted on a segment (crossing point or refinement split)
  Free,       // inserted in the interior by refinement
  Dead,       // deleted; used by no triangle
};

struct Subsegment {
  VertexId a = kNone, b = kNone;  // endpoints
  int marker = 0;                 // boundary marker of the input segment it belongs to
  std::uint32_t segment = kNone;  // index of the input segment it is part of
};

namespace detail {
struct TopologyWriter;  // mesh/topology_writer.h: the kernel's write access
}

// One of the dense topology arrays (corner, link; subseg is sparse, mesh/subsegment_slots.h): anyone
// reads it like a vector (m.corner[e], m.corner.size()); only Mesh's own members and the kernel's operations, through
// detail::TopologyWriter, write it. Everything is inline: reads cost what a vector's do.
template <class T>
class TopologyArray {
 public:
  using value_type = T;
  const T& operator[](std::size_t i) const { return slots_[i]; }
  std::size_t size() const { return slots_.size(); }
  std::size_t capacity() const { return slots_.capacity(); }
  bool empty() const { return slots_.empty(); }
  const T* data() const { return slots_.data(); }
  auto begin() const { return slots_.begin(); }
  auto end() const { return slots_.end(); }
  // Equal contents (tests compare meshes and snapshots slot by slot).
  friend bool operator==(const TopologyArray& a, const TopologyArray& b) { return a.slots_ == b.slots_; }
  friend bool operator==(const TopologyArray& a, const BigVector<T>& b) { return a.slots_ == b; }

 private:
  friend struct Mesh;
  friend struct detail::TopologyWriter;
  BigVector<T> slots_;
};

struct Mesh {
  // Vertices. A new per-vertex array must also be carried by part_with, take_vertices and
  // hold_only / hold_all (mesh/parts.cpp).
  BigVector<Point> points;
  std::vector<VertexKind> kind;
  std::vector<int> marker;          // empty when nothing carries markers
  int num_attributes = 0;
  std::vector<double> attributes;   // num_attributes per vertex

  // Triangles: the topology, read by all, written by src/mesh/ only.
  TopologyArray<VertexId> corner;
  TopologyArray<EdgeRef> link;
  SubsegmentSlots subseg;
  std::vector<TriangleId> free_triangles;
  int num_triangle_attributes = 0;
  std::vector<double> triangle_attributes;  // num_triangle_attributes per triangle
  std::vector<double> area_bound;           // empty, or one per triangle (<= 0: no bound)

  std::vector<Subsegment> subsegments;

  // --- navigation ---
  VertexId org(EdgeRef e) const { return corner[e]; }
  VertexId dest(EdgeRef e) const { return corner[lnext(e)]; }
  VertexId apex(EdgeRef e) const { return corner[lprev(e)]; }
  EdgeRef sym(EdgeRef e) const { return link[e]; }
  EdgeRef onext(EdgeRef e) const { return link[lprev(e)]; }
  EdgeRef oprev(EdgeRef e) const { return link[e] == kNone ? kNone : lnext(link[e]); }
  const Point& point(VertexId v) const { return points[v]; }

  // Triangle t's corners, counter-clockwise: the ids, a pointer to the three, and their points.
  std::array<VertexId, 3> corners(TriangleId t) const {
    return {corner[edge_of(t, 0)], corner[edge_of(t, 1)], corner[edge_of(t, 2)]};
  }
  const VertexId* corners_at(TriangleId t) const { return &corner[edge_of(t, 0)]; }
  struct CornerPoints {
    const Point& a;
    const Point& b;
    const Point& c;
  };
  CornerPoints corner_points(TriangleId t) const {
    return {points[corner[edge_of(t, 0)]], points[corner[edge_of(t, 1)]], points[corner[edge_of(t, 2)]]};
  }

  std::uint32_t triangle_slots() const { return static_cast<std::uint32_t>(corner.size() / 3); }
  bool is_live(TriangleId t) const { return corner[edge_of(t, 0)] != kNone; }
  std::uint32_t live_triangles() const {
    return triangle_slots() - static_cast<std::uint32_t>(free_triangles.size());
  }
  std::uint32_t vertex_count() const { return static_cast<std::uint32_t>(points.size()); }
  bool has_subsegments() const { return !subseg.empty(); }

  // --- storage primitives (topology-free) ---
  // A new triangle a, b, c (counter-clockwise) with no links, reusing a dead slot if there is one.
  TriangleId add_triangle(VertexId a, VertexId b, VertexId c);
  // add_triangle's new slot at the end of the arrays.
  TriangleId append_triangle(VertexId a, VertexId b, VertexId c);
  // Marks t dead and unlinks its neighbours from it.
  void kill_triangle(TriangleId t);
  // Makes e and f twins.
  void bond(EdgeRef e, EdgeRef f) {
    link.slots_[e] = f;
    link.slots_[f] = e;
  }
  // Adds a vertex and returns its id; attributes are zero and the marker 0.
  VertexId add_vertex(const Point& p, VertexKind k);
  // Gives vertex v, which lies on the line a-b, the attributes of a and b interpolated linearly by
  // its position along a-b (as every vertex added on a segment gets them).
  void interpolate_attributes(VertexId v, VertexId a, VertexId b);
  // Ensures the subsegment array exists (all kNone) so edges can carry segments.
  void enable_subsegments();
  // Attaches subsegment s to edge e and its twin.
  void set_subsegment(EdgeRef e, SubsegmentId s) {
    subseg.set(e, s);
    if (link[e] != kNone) subseg.set(link[e], s);
  }
  // Room for `edges` more constrained edge slots (a subsegment holds one per side) without the
  // subsegment table growing on the way: a capacity, no topology. Segment insertion knows its
  // count up front, and growing the table by doublings was half of its time on the holes.
  void reserve_constrained_edges(std::size_t edges) { subseg.reserve_entries(edges); }
  // Room for `triangles` triangles in the triangle arrays without a reallocation.
  void reserve_triangles(std::size_t triangles) {
    corner.slots_.reserve(3 * triangles);
    link.slots_.reserve(3 * triangles);
    if (has_subsegments()) subseg.reserve(3 * triangles);
  }
  // Moves live triangles over dead slots so that every slot is live (ids change).
  void compact_triangles();

  // --- sub-meshes (refine/refine_in_parts.cpp cuts a mesh in two and joins the halves again) ---
  // A mesh with the given vertices of this one (every per-vertex array), the given subsegment
  // records (their endpoints renumbered alike) and the attribute layouts, and no triangles, into
  // which part of the triangles can be moved: its vertex i is vertices[i] and its record i is
  // records[i], both lists increasing, so ids keep their order. It holds only what the part uses.
  Mesh part_with(const std::vector<VertexId>& vertices, const std::vector<SubsegmentId>& records) const;
  // Appends from's vertices with ids from `first` on, with all their per-vertex data (as the
  // vertices numbered after this mesh's own); from's points are freed as they are copied.
  void take_vertices(Mesh& from, VertexId first);
};

// The per-triangle arrays besides the topology (corner, link, subseg), each holding the same
// number of values for every slot (or none at all): a new one is listed here, and the operations
// that move triangles between meshes (mesh/parts.h) carry it. The kernel's slot-by-slot storage
// code names each array itself and must learn the new one too: append_triangle (which grows it)
// and compact_triangles (mesh.cpp), copy_triangle_data (internal.h), clear_triangles (assemble.cpp).
inline constexpr std::vector<double> Mesh::*kTriangleData[] = {&Mesh::triangle_attributes, &Mesh::area_bound};

}  // namespace deltri
