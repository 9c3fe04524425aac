#include "mesh/recover_edge.h"

namespace deltri {

bool EdgeRecovery::crosses(EdgeRef e, VertexId u, VertexId v) {
  const Mesh& mesh = ed_.mesh;
  const VertexId a = mesh.org(e), b = mesh.dest(e);
  if (a == u || a == v || b == u || b == v) return false;
  // Inside the cavity a line crossing can only be a crossing of the open segment (the cavity
  // meets the line exactly in that segment), so the signs of the endpoints decide.
  const double sa = ed_.pred.orient2d(mesh.point(u), mesh.point(v), mesh.point(a));
  const double sb = ed_.pred.orient2d(mesh.point(u), mesh.point(v), mesh.point(b));
  return (sa > 0.0 && sb < 0.0) || (sa < 0.0 && sb > 0.0);
}

EdgeRef EdgeRecovery::edge_of_crossing(const Crossing& c) {
  const Mesh& mesh = ed_.mesh;
  // Where it was seen, if no flip has moved it: a valid mesh has one edge a->b.
  if (mesh.corner[c.seen] == c.a && mesh.corner[lnext(c.seen)] == c.b) return c.seen;
  return ed_.find(c.a, c.b);
}

void EdgeRecovery::remove_crossings(VertexId u, VertexId v, const std::vector<EdgeRef>& crossed) {
  // Sloan's order: a crossing edge that cannot be flipped yet, or whose flip still crosses, goes
  // to the back of a FIFO holding each crossing edge once. Edges are named by their ends because
  // flips move edges between slots.
  Mesh& mesh = ed_.mesh;
  queue_.clear();
  for (const EdgeRef g : crossed) queue_.push_back({mesh.org(g), mesh.dest(g), g});
  for (std::size_t head = 0; head < queue_.size(); ++head) {
    if (head >= 1024 && 2 * head >= queue_.size()) {  // drop the consumed front: memory stays linear
      queue_.erase(queue_.begin(), queue_.begin() + static_cast<std::ptrdiff_t>(head));
      head = 0;
    }
    const Crossing c = queue_[head];
    const EdgeRef e = edge_of_crossing(c);
    if (!ed_.flippable(e)) {
      queue_.push_back({c.a, c.b, e});
      continue;
    }
    ed_.flip(e);
    const EdgeRef diagonal = lnext(e);
    if (crosses(diagonal, u, v)) queue_.push_back({mesh.org(diagonal), mesh.dest(diagonal), diagonal});
  }
}

void EdgeRecovery::restore_delaunay() {
  const Mesh& mesh = ed_.mesh;
  stack_.clear();
  for (const TriangleId t : cavity_)
    for (unsigned i = 0; i < 3; ++i) stack_.push_back(edge_of(t, i));
  // Flips reuse the cavity's slots, so the stamps still say which triangles are in it.
  ed_.legalize(stack_, [&](EdgeRef e) {
    const EdgeRef f = mesh.link[e];
    if (f == kNone || mesh.subseg.has(e) || !in_cavity(triangle_of(f))) return false;
    return in_cavity(triangle_of(e)) && ed_.violates_delaunay(e);
  });
}

EdgeRef EdgeRecovery::recover(VertexId u, VertexId v, const std::vector<EdgeRef>& crossed,
                              SubsegmentId id) {
  Mesh& mesh = ed_.mesh;
  if (++round_ == 0) {  // the stamps wrapped: forget them all
    stamp_.assign(stamp_.size(), 0);
    round_ = 1;
  }
  if (stamp_.size() < mesh.triangle_slots()) stamp_.resize(mesh.triangle_slots(), 0);
  cavity_.clear();
  for (const EdgeRef g : crossed)
    for (const TriangleId t : {triangle_of(g), triangle_of(mesh.link[g])})
      if (stamp_[t] != round_) {
        stamp_[t] = round_;
        cavity_.push_back(t);
      }
  remove_crossings(u, v, crossed);
  const EdgeRef uv = ed_.find(u, v);
  // Constrained before the Lawson pass, so it is never flipped away.
  if (uv != kNone) mesh.set_subsegment(uv, id);
  restore_delaunay();
  return uv == kNone ? kNone : ed_.find(u, v);
}

}  // namespace deltri
