// Helpers shared by the mesh operations in this directory; not part of the public API.
#pragma once

#include "geometry/predicates.h"
#include "mesh/mesh.h"
#include "mesh/topology_writer.h"

namespace deltri {
struct KnownCavity;
}

namespace deltri::detail {

// Ghost triangles carry kGhostVertex as one corner; geometry must never be asked about them.
inline bool is_ghost(const Mesh& m, TriangleId t) {
  return m.corner[edge_of(t, 0)] == kGhostVertex || m.corner[edge_of(t, 1)] == kGhostVertex ||
         m.corner[edge_of(t, 2)] == kGhostVertex;
}

inline bool carries_subsegment(const Mesh& m, EdgeRef e) {
  return !m.subseg.empty() && m.subseg.has(e);
}

// What lies across an edge: the twin and the subsegment. Saved before corners are rewritten so the
// neighbourhood can be re-attached to whichever slot ends up holding the same edge.
struct EdgeSurround {
  EdgeRef link = kNone;
  SubsegmentId seg = kNone;
};

inline EdgeSurround surround_of(const Mesh& m, EdgeRef e) {
  return {m.link[e], m.subseg.empty() ? kNone : m.subseg[e]};
}

// Makes `link` (kNone: none) e's twin.
inline void link_to(Mesh& m, EdgeRef e, EdgeRef link) {
  detail::link_slots(m)[e] = link;
  if (link != kNone) detail::link_slots(m)[link] = e;
}

inline void attach(Mesh& m, EdgeRef e, EdgeSurround s) {
  link_to(m, e, s.link);
  if (!m.subseg.empty()) detail::subseg_slots(m).set(e, s.seg);
}

// Kills t and clears its slots' subsegments (kill_triangle leaves them for
// drop_unused_subsegments), for a triangle whose subsegments now live elsewhere.
inline void kill_with_subsegments(Mesh& m, TriangleId t) {
  m.kill_triangle(t);
  detail::subseg_slots(m).set_triangle(edge_of(t, 0), kNone);
}

// Bonds two edges that are new to each other and therefore interior to the change: no subsegment.
inline void bond_inner(Mesh& m, EdgeRef e, EdgeRef f) {
  m.bond(e, f);
  if (!m.subseg.empty()) {
    detail::subseg_slots(m).set(e, kNone);
    detail::subseg_slots(m).set(f, kNone);
  }
}

// Children of a split triangle inherit its region attributes and area bound.
inline void copy_triangle_data(Mesh& m, TriangleId from, TriangleId to) {
  const int na = m.num_triangle_attributes;
  for (int k = 0; k < na; ++k)
    m.triangle_attributes[static_cast<std::size_t>(to) * na + k] =
        m.triangle_attributes[static_cast<std::size_t>(from) * na + k];
  if (!m.area_bound.empty()) m.area_bound[to] = m.area_bound[from];
}

// Frees a slot whose neighbours have already been re-attached elsewhere, so they must not be
// unlinked by kill_triangle.
inline void release(Mesh& m, TriangleId t) {
  detail::link_slots(m)[edge_of(t, 0)] = detail::link_slots(m)[edge_of(t, 1)] = detail::link_slots(m)[edge_of(t, 2)] = kNone;
  m.kill_triangle(t);
}

// The side of t whose origin is v, or 3 if v is not a corner of t.
inline unsigned corner_index(const Mesh& m, TriangleId t, VertexId v) {
  unsigned i = 0;
  while (i < 3 && m.corner[edge_of(t, i)] != v) ++i;
  return i;
}

// Replaces the triangles of `cavity` (a disk with no vertex inside, v strictly inside it and
// seeing every boundary edge from the inside) by the fan of triangles from v to its recorded
// boundary. Returns an edge leaving v, or kNone, with nothing changed, when the cavity is not
// such a disk or is too large for the fan's fixed arrays.
EdgeRef fill_star(Mesh& m, Predicates& pred, VertexId v, const KnownCavity& cavity);

}  // namespace deltri::detail
