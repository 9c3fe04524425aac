// Bowyer-Watson on a cavity found in advance: its k triangles give way to the k + 2 triangles
// that join the new vertex to the cavity's boundary edges. Lawson's flips reach the same
// triangulation, but write each triangle up to three times (the split, then a flip per cavity
// triangle beyond the first); here each is written once.
#include "mesh/internal.h"
#include "mesh/operations.h"
#include "mesh/topology_writer.h"

namespace deltri::detail {
namespace {

constexpr std::size_t kMaxFan = 64;

// Whether v sees every boundary edge from the inside. An edge with a triangle across needs no
// test: v lies in the cavity triangle's circumcircle and not in the other's, and the part of one
// circle outside the other lies strictly on the first one's side of their common chord.
// Subsegments and the mesh boundary carry no such argument.
bool sees_boundary(const Mesh& m, Predicates& pred, VertexId v, std::span<const EdgeRef> boundary) {
  for (EdgeRef e : boundary)
    if ((m.link[e] == kNone || carries_subsegment(m, e)) &&
        pred.orient2d(m.point(m.org(e)), m.point(m.dest(e)), m.point(v)) <= 0)
      return false;
  return true;
}

// next[j] = the boundary edge that starts where edge j ends; false unless the edges close into
// one loop, so that the boundary does not touch itself.
bool chain(const VertexId* org, const VertexId* dest, std::size_t n, std::uint8_t* next) {
  for (std::size_t j = 0; j < n; ++j) {
    // The search lists each triangle's boundary edges together, in order: the next edge is often
    // the next one listed.
    std::size_t i = j + 1 < n && org[j + 1] == dest[j] ? j + 1 : 0;
    while (i < n && org[i] != dest[j]) ++i;
    if (i == n) return false;
    next[j] = static_cast<std::uint8_t>(i);
  }
  std::size_t j = next[0], steps = 1;
  for (; j != 0 && steps < n; ++steps) j = next[j];
  return j == 0 && steps == n;
}

}  // namespace

EdgeRef fill_star(Mesh& m, Predicates& pred, VertexId v, const KnownCavity& cavity) {
  const std::span<const EdgeRef> boundary = cavity.boundary;
  const std::size_t n = boundary.size();
  // Euler: a disk of k triangles with no vertex inside has k + 2 boundary edges.
  if (n != cavity.triangles + 2 || n > kMaxFan) return kNone;
  VertexId org[kMaxFan], dest[kMaxFan];
  for (std::size_t j = 0; j < n; ++j) org[j] = m.org(boundary[j]), dest[j] = m.dest(boundary[j]);
  std::uint8_t next[kMaxFan];
  if (!chain(org, dest, n, next) || !sees_boundary(m, pred, v, boundary)) return kNone;
  // Plain arrays: an array of EdgeSurround would spend kMaxFan default initialisations on a fan
  // of about 7.
  EdgeRef outside_link[kMaxFan];
  SubsegmentId outside_seg[kMaxFan];
  for (std::size_t j = 0; j < n; ++j) {
    const EdgeSurround around = surround_of(m, boundary[j]);
    outside_link[j] = around.link, outside_seg[j] = around.seg;
  }
  // Each cavity triangle's first boundary edge keeps its slot, and with it the triangle's
  // attributes; the other edges take the slots of the triangles without boundary edges, then two
  // new ones, and copy their owners' attributes (owners keep their slots, so those are intact).
  // The search lists a triangle's boundary edges together.
  TriangleId slot[kMaxFan];
  std::size_t spare = 0;
  const bool segments = m.has_subsegments();
  for (std::size_t j = 0; j < n; ++j) {
    const TriangleId owner = triangle_of(boundary[j]);
    const bool first = j == 0 || triangle_of(boundary[j - 1]) != owner;
    slot[j] = first                        ? owner
              : spare < cavity.inner.size() ? cavity.inner[spare++]
                                            : m.add_triangle(kNone, kNone, kNone);
    const EdgeRef e = edge_of(slot[j], 0);
    detail::corner_slots(m)[e] = org[j];
    detail::corner_slots(m)[e + 1] = dest[j];
    detail::corner_slots(m)[e + 2] = v;
    // The outside's subsegment on edge 0, none on the inner edges 1 and 2, in one write.
    link_to(m, e, outside_link[j]);
    if (segments) detail::subseg_slots(m).set_triangle(e, outside_seg[j]);
    if (!first) copy_triangle_data(m, owner, slot[j]);
  }
  for (std::size_t j = 0; j < n; ++j) m.bond(edge_of(slot[j], 1), edge_of(slot[next[j]], 2));
  return edge_of(slot[0], 2);
}

}  // namespace deltri::detail
