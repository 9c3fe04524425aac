#include "mesh/vertex_edges.h"

#include <algorithm>
#include <deque>

namespace deltri {
namespace {

constexpr int kLocalSearchLimit = 64;
constexpr std::size_t kGrowthStep = 1024;

bool leaves(const Mesh& mesh, EdgeRef e, VertexId v) {
  return e != kNone && e < mesh.corner.size() && mesh.is_live(triangle_of(e)) && mesh.org(e) == v;
}

EdgeRef corner_edge(const Mesh& mesh, TriangleId t, VertexId v) {
  for (unsigned i = 0; i < 3; ++i)
    if (mesh.corner[edge_of(t, i)] == v) return edge_of(t, i);
  return kNone;
}

// Breadth-first over neighbours of the slot that once held v: flips keep triangles local.
EdgeRef search_near(const Mesh& mesh, TriangleId start, VertexId v) {
  if (!mesh.is_live(start)) return kNone;
  std::deque<TriangleId> todo{start};
  std::vector<TriangleId> seen{start};
  for (int steps = 0; !todo.empty() && steps < kLocalSearchLimit; ++steps) {
    const TriangleId t = todo.front();
    todo.pop_front();
    if (const EdgeRef e = corner_edge(mesh, t, v); e != kNone) return e;
    for (unsigned i = 0; i < 3; ++i) {
      const EdgeRef twin = mesh.link[edge_of(t, i)];
      if (twin == kNone) continue;
      const TriangleId n = triangle_of(twin);
      bool known = false;
      for (TriangleId s : seen) known = known || s == n;
      if (!known) {
        seen.push_back(n);
        todo.push_back(n);
      }
    }
  }
  return kNone;
}

}  // namespace

// Room for every vertex the mesh has room for from the start (see grow_to): an exact-size index
// was abandoned at the first new vertex, and stayed resident in the malloc arena.
VertexEdges::VertexEdges(const Mesh& mesh) {
  out_.reserve(std::max<std::size_t>(mesh.vertex_count(), mesh.points.capacity()));
  out_.assign(mesh.vertex_count(), kNone);
  for (EdgeRef e{0}; e < mesh.corner.size(); ++e)
    if (mesh.corner[e] != kNone) out_[mesh.corner[e]] = e;
}

// Room for every vertex the mesh has room for (refinement reserves its expected count up front,
// parts included): the index doubled as vertices came instead, and each abandoned copy stayed
// resident in the refining thread's malloc arena. Untouched room costs no memory.
void VertexEdges::grow_to(const Mesh& mesh, VertexId v) {
  if (v >= out_.capacity())
    out_.reserve(std::max<std::size_t>({std::size_t{v} + 1, 2 * out_.capacity(), mesh.points.capacity()}));
  // Sized a step ahead, so that vertices appended one at a time do not each call resize (about 1%
  // of the unit square's refinement); entries past the last vertex are kNone either way.
  out_.resize(std::min(out_.capacity(), std::size_t{v} + kGrowthStep), kNone);
}

void VertexEdges::note_star(const Mesh& mesh, EdgeRef out) {
  for_each_around(mesh, out, [&](EdgeRef e) {
    note(mesh, e);
    note(mesh, lnext(e));
    note(mesh, lprev(e));
  });
}

EdgeRef VertexEdges::leaving(const Mesh& mesh, VertexId v) {
  if (v >= out_.size()) grow_to(mesh, v);
  const EdgeRef hint = out_[v];
  if (leaves(mesh, hint, v)) return hint;
  EdgeRef found = hint != kNone && hint < mesh.corner.size() ? search_near(mesh, triangle_of(hint), v)
                                                             : kNone;
  for (EdgeRef e{0}; found == kNone && e < mesh.corner.size(); ++e)
    if (mesh.corner[e] == v) found = e;
  out_[v] = found;
  return found;
}

EdgeRef VertexEdges::find(const Mesh& mesh, VertexId a, VertexId b) {
  const EdgeRef out = leaving(mesh, a);
  if (out == kNone) return kNone;
  EdgeRef found = kNone;
  for_each_around(mesh, out, [&](EdgeRef e) {
    if (mesh.dest(e) == b) found = e;
    // The last edge of an open fan is lprev of the last triangle, reversed: check it too.
    if (mesh.apex(e) == b && found == kNone) found = lprev(e);
  });
  if (found != kNone && mesh.org(found) != a) {
    // lprev(e) runs b -> a; the caller wants a -> b, which is its twin when there is one.
    const EdgeRef twin = mesh.link[found];
    return twin != kNone ? twin : found;
  }
  return found;
}

}  // namespace deltri
