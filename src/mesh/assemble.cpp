#include "mesh/assemble.h"
#include "mesh/topology_writer.h"

#include <algorithm>
#include <vector>

namespace deltri {

void clear_triangles(Mesh& mesh) {
  detail::corner_slots(mesh).clear();
  detail::link_slots(mesh).clear();
  detail::subseg_slots(mesh).clear();
  mesh.free_triangles.clear();
  mesh.triangle_attributes.clear();
  mesh.area_bound.clear();
}

void reserve_triangles(Mesh& mesh, std::size_t triangles) {
  detail::corner_slots(mesh).reserve(mesh.corner.size() + 3 * triangles);
  detail::link_slots(mesh).reserve(mesh.link.size() + 3 * triangles);
}

TriangleId append_unlinked(Mesh& mesh, VertexId a, VertexId b, VertexId c) {
  return mesh.append_triangle(a, b, c);
}

bool pair_twins(Mesh& mesh, EdgeRef e, EdgeRef f) {
  if (mesh.org(f) != mesh.dest(e) || mesh.dest(f) != mesh.org(e) || mesh.link[f] != kNone) return false;
  mesh.bond(e, f);
  return true;
}

namespace {

struct EdgeKey {
  std::uint64_t key;  // smaller vertex id in the high half
  EdgeRef edge;
  bool operator<(const EdgeKey& o) const { return key < o.key || (key == o.key && edge < o.edge); }
};

std::uint64_t undirected(VertexId a, VertexId b) {
  const VertexId lo = std::min(a, b), hi = std::max(a, b);
  return (static_cast<std::uint64_t>(lo) << 32) | hi;
}

using Kind = AssemblyProblem::Kind;

AssemblyProblem add_triangles(Mesh& mesh, Predicates& pred, std::span<const std::uint32_t> corners,
                              std::uint32_t count, std::uint32_t stride) {
  detail::corner_slots(mesh).assign(3 * static_cast<std::size_t>(count), kNone);
  detail::link_slots(mesh).assign(3 * static_cast<std::size_t>(count), kNone);
  detail::subseg_slots(mesh).clear();
  mesh.free_triangles.clear();
  for (TriangleId t{0}; t < count; ++t) {
    const std::uint32_t* in = &corners[static_cast<std::size_t>(t) * stride];
    const VertexId c[3] = {VertexId{in[0]}, VertexId{in[1]}, VertexId{in[2]}};
    if (c[0] == c[1] || c[1] == c[2] || c[2] == c[0]) return {Kind::RepeatedVertex, t};
    if (pred.orient2d(mesh.point(c[0]), mesh.point(c[1]), mesh.point(c[2])) <= 0) return {Kind::Clockwise, t};
    for (unsigned i = 0; i < 3; ++i) detail::corner_slots(mesh)[edge_of(t, i)] = c[i];
  }
  return {};
}

AssemblyProblem pair_edges(Mesh& mesh) {
  std::vector<EdgeKey> keys(mesh.corner.size());
  for (EdgeRef e{0}; e < mesh.corner.size(); ++e) keys[e] = {undirected(mesh.org(e), mesh.dest(e)), e};
  std::sort(keys.begin(), keys.end());
  for (std::size_t i = 0; i < keys.size();) {
    std::size_t j = i + 1;
    while (j < keys.size() && keys[j].key == keys[i].key) ++j;
    const EdgeRef e = keys[i].edge;
    if (j - i > 2) return {Kind::SharedEdge, triangle_of(e)};
    if (j - i == 2) {
      const EdgeRef f = keys[i + 1].edge;
      if (mesh.org(e) == mesh.org(f)) return {Kind::Overlap, triangle_of(e), triangle_of(f)};
      mesh.bond(e, f);
    }
    i = j;
  }
  return {};
}

}  // namespace

AssemblyProblem assemble_triangles(Mesh& mesh, Predicates& pred, std::span<const std::uint32_t> corners,
                                   std::uint32_t count, std::uint32_t stride) {
  const AssemblyProblem added = add_triangles(mesh, pred, corners, count, stride);
  return added.kind != Kind::None ? added : pair_edges(mesh);
}

}  // namespace deltri
