#include "cdt/rebuild_mesh.h"

#include <algorithm>
#include <cstdint>

#include "cdt/edit.h"
#include "mesh/overlap.h"
#include "pslg/errors.h"

namespace deltri {
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

std::string triangle_name(TriangleId t) { return "triangle #" + std::to_string(t + 1) + " (in file order)"; }

void add_triangles(Mesh& mesh, Predicates& pred, const EleData& ele, const std::string& path) {
  const std::uint32_t n = ele.triangle_count();
  const std::uint32_t stride = ele.nodes_per_triangle;
  mesh.corner.assign(3 * static_cast<std::size_t>(n), kNone);
  mesh.link.assign(3 * static_cast<std::size_t>(n), kNone);
  mesh.free_triangles.clear();
  for (TriangleId t = 0; t < n; ++t) {
    const std::uint32_t* c = &ele.corners[static_cast<std::size_t>(t) * stride];
    if (c[0] == c[1] || c[1] == c[2] || c[2] == c[0])
      throw InputError(path, 0, triangle_name(t) + " repeats a vertex");
    if (pred.orient2d(mesh.point(c[0]), mesh.point(c[1]), mesh.point(c[2])) <= 0)
      throw InputError(path, 0, triangle_name(t) + " is not counter-clockwise");
    for (unsigned i = 0; i < 3; ++i) mesh.corner[3 * t + i] = c[i];
  }
}

void pair_edges(Mesh& mesh, const std::string& path) {
  std::vector<EdgeKey> keys(mesh.corner.size());
  for (EdgeRef e = 0; e < mesh.corner.size(); ++e) keys[e] = {undirected(mesh.org(e), mesh.dest(e)), e};
  std::sort(keys.begin(), keys.end());
  for (std::size_t i = 0; i < keys.size();) {
    std::size_t j = i + 1;
    while (j < keys.size() && keys[j].key == keys[i].key) ++j;
    const EdgeRef e = keys[i].edge;
    if (j - i > 2)
      throw InputError(path, 0, "an edge is shared by more than two triangles (" + triangle_name(triangle_of(e)) + ")");
    if (j - i == 2) {
      const EdgeRef f = keys[i + 1].edge;
      if (mesh.org(e) == mesh.org(f))
        throw InputError(path, 0, triangle_name(triangle_of(e)) + " and " + triangle_name(triangle_of(f)) + " overlap");
      mesh.bond(e, f);
    }
    i = j;
  }
}

// A six-node .ele (-o2) lists the edge midpoints as nodes 4 to 6. They are no corners of the
// rebuilt mesh, and refinement makes its own, so, as Triangle does, they leave the mesh: a vertex
// named only as a midpoint is marked Dead and is not written (a -r chain of quadratic meshes would
// otherwise gather unused vertices, pairs of them on the same point).
void drop_midpoint_nodes(Mesh& mesh, const EleData& ele) {
  if (ele.nodes_per_triangle != 6) return;
  std::vector<char> role(mesh.vertex_count(), 0);  // 1: corner, 2: midpoint only
  for (std::size_t i = 0; i < ele.corners.size(); ++i) {
    const std::uint32_t v = ele.corners[i];
    if (i % 6 < 3) role[v] = 1;
    else if (role[v] == 0) role[v] = 2;
  }
  for (VertexId v = 0; v < mesh.vertex_count(); ++v)
    if (role[v] == 2) mesh.kind[v] = VertexKind::Dead;
}

}  // namespace

void rebuild_mesh(Mesh& mesh, Predicates& pred, const EleData& ele, const std::string& ele_path) {
  add_triangles(mesh, pred, ele, ele_path);
  pair_edges(mesh, ele_path);
  // Paired edges and counter-clockwise triangles can still cross or lie over one another.
  if (const auto found = find_overlap(mesh, pred))
    throw InputError(ele_path, 0,
                     triangle_name(found->first) + " and " + triangle_name(found->second) +
                         (found->interiors_overlap ? " overlap" : " meet other than at shared corners (a corner of one lies on the other)"));
  mesh.num_triangle_attributes = ele.num_attributes;
  mesh.triangle_attributes = ele.attributes;
  mesh.subseg.clear();
  drop_midpoint_nodes(mesh, ele);
}

void protect_boundary(Mesh& mesh) {
  mesh.enable_subsegments();
  for (EdgeRef e = 0; e < mesh.corner.size(); ++e) {
    if (mesh.corner[e] == kNone || mesh.link[e] != kNone || mesh.subseg[e] != kNone) continue;
    const SubsegmentId s = static_cast<SubsegmentId>(mesh.subsegments.size());
    mesh.subsegments.push_back({mesh.org(e), mesh.dest(e), 1, kNone});
    mesh.set_subsegment(e, s);
  }
}

void make_constrained_delaunay(Mesh& mesh, Predicates& pred) {
  CdtEditor editor(mesh, pred);
  for (EdgeRef e = 0; e < mesh.corner.size(); ++e)
    if (mesh.corner[e] != kNone && mesh.link[e] != kNone && mesh.link[e] > e) editor.legalize_from(e);
}

}  // namespace deltri
