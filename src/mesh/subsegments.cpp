#include "mesh/subsegments.h"
#include "mesh/internal.h"
#include "mesh/topology_writer.h"

#include <vector>

namespace deltri {

SubsegmentId constrain(Mesh& mesh, EdgeRef e, const Subsegment& s) {
  mesh.subsegments.push_back(s);
  const SubsegmentId id = static_cast<SubsegmentId>(mesh.subsegments.size() - 1);
  mesh.set_subsegment(e, id);
  return id;
}

Subsegment unconstrain(Mesh& mesh, EdgeRef e) {
  const SubsegmentId id = mesh.subseg[e];
  const Subsegment old = mesh.subsegments[id];
  mesh.subsegments[id].a = kNone;
  mesh.set_subsegment(e, kNone);
  return old;
}

std::size_t constrain_boundary(Mesh& mesh, int marker) {
  mesh.enable_subsegments();
  std::size_t added = 0;
  for (EdgeRef e{0}; e < mesh.corner.size(); ++e) {
    if (mesh.corner[e] == kNone || mesh.link[e] != kNone || mesh.subseg.has(e)) continue;
    constrain(mesh, e, {mesh.org(e), mesh.dest(e), marker, kNone});
    ++added;
  }
  return added;
}

void drop_dead_subsegments(Mesh& mesh) {
  std::vector<SubsegmentId> renumber(mesh.subsegments.size(), kNone);
  SubsegmentId next{0};
  for (SubsegmentId s{0}; s < mesh.subsegments.size(); ++s) {
    if (mesh.subsegments[s].a == kNone) continue;
    renumber[s] = next;
    mesh.subsegments[next++] = mesh.subsegments[s];
  }
  if (next == mesh.subsegments.size()) return;
  mesh.subsegments.resize(next);
  detail::subseg_slots(mesh).remap([&](SubsegmentId s) { return renumber[s]; });
}

std::size_t drop_unused_subsegments(Mesh& mesh) {
  if (!mesh.has_subsegments()) return 0;
  std::vector<char> used(mesh.subsegments.size(), 0);
  std::vector<EdgeRef> dead;  // kill_triangle leaves subseg entries in dead slots
  mesh.subseg.for_each([&](EdgeRef e, SubsegmentId s) {
    if (mesh.corner[e] != kNone)
      used[s] = 1;
    else
      dead.push_back(e);
  });
  std::size_t dropped = 0;
  for (SubsegmentId s{0}; s < used.size(); ++s)
    if (!used[s] && mesh.subsegments[s].a != kNone) {
      mesh.subsegments[s].a = kNone;
      ++dropped;
    }
  // Cleared before renumbering.
  detail::subseg_slots(mesh).erase_all(dead);
  drop_dead_subsegments(mesh);
  return dropped;
}

PeeledEdges peel_boundary_triangle(Mesh& mesh, EdgeRef e) {
  const VertexId a = mesh.org(e), b = mesh.dest(e), v = mesh.apex(e);
  const PeeledEdges out{mesh.link[lprev(e)], mesh.link[lnext(e)]};  // a -> v and v -> b beyond
  const SubsegmentId id = mesh.subseg[e];
  const Subsegment old = mesh.subsegments[id];
  const TriangleId t = triangle_of(e);
  detail::kill_with_subsegments(mesh, t);
  mesh.subsegments[id] = {a, v, old.marker, old.segment};
  mesh.set_subsegment(out.av, id);
  constrain(mesh, out.vb, {v, b, old.marker, old.segment});
  return out;
}

}  // namespace deltri
