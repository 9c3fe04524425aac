// Point location by a stochastic visibility walk with exact orientation tests. The walk is only
// trusted where it is provably finite and conclusive; otherwise a scan of every triangle decides.
#include <cstdint>

#include "mesh/internal.h"
#include "mesh/operations.h"

namespace deltri {
namespace {

// The walk leaves through a pseudo-randomly chosen side among those that see p, which keeps it
// from circling forever in meshes that are not Delaunay; a fixed seed keeps results repeatable.
struct SideChooser {
  std::uint32_t state = 0x9E3779B9u;
  unsigned first() {
    state ^= state << 13;
    state ^= state >> 17;
    state ^= state << 5;
    return state % 3;
  }
};

Location classify(TriangleId t, const double (&o)[3]) {
  const bool z0 = o[0] == 0, z1 = o[1] == 0, z2 = o[2] == 0;
  // Two collinear sides meet at the vertex between them: the origin of the later side.
  if (z0 && z1) return {LocateStatus::OnVertex, edge_of(t, 1)};
  if (z1 && z2) return {LocateStatus::OnVertex, edge_of(t, 2)};
  if (z2 && z0) return {LocateStatus::OnVertex, edge_of(t, 0)};
  for (unsigned i = 0; i < 3; ++i)
    if (o[i] == 0) return {LocateStatus::OnEdge, edge_of(t, i)};
  return {LocateStatus::InTriangle, edge_of(t, 0)};
}

double side_test(const Mesh& m, Predicates& pred, EdgeRef e, const Point& p) {
  return pred.orient2d(m.point(m.org(e)), m.point(m.dest(e)), p);
}

// The triangle containing p among all live real triangles, or Outside with a boundary edge that p
// is strictly right of (`fallback` if that is one).
Location scan(const Mesh& m, Predicates& pred, const Point& p, EdgeRef fallback) {
  for (TriangleId t{0}; t < m.triangle_slots(); ++t) {
    if (!m.is_live(t) || detail::is_ghost(m, t)) continue;
    double o[3];
    bool inside = true;
    for (unsigned i = 0; i < 3 && inside; ++i)
      inside = (o[i] = side_test(m, pred, edge_of(t, i), p)) >= 0;
    if (inside) return classify(t, o);
  }
  if (fallback != kNone) return {LocateStatus::Outside, fallback};
  for (EdgeRef e{0}; e < m.corner.size(); ++e) {
    const TriangleId t = triangle_of(e);
    if (!m.is_live(t) || detail::is_ghost(m, t)) continue;
    const bool boundary = m.link[e] == kNone || detail::is_ghost(m, triangle_of(m.link[e]));
    if (boundary && side_test(m, pred, e, p) < 0) return {LocateStatus::Outside, e};
  }
  return {LocateStatus::Outside, kNone};
}

// A live real triangle to start from: the hint's, its real neighbour if the hint is a ghost, or
// the first live real triangle.
TriangleId start_triangle(const Mesh& m, EdgeRef hint) {
  if (hint != kNone && hint < m.corner.size() && m.is_live(triangle_of(hint))) {
    const TriangleId t = triangle_of(hint);
    if (!detail::is_ghost(m, t)) return t;
    for (unsigned i = 0; i < 3; ++i) {
      const EdgeRef e = edge_of(t, i);
      if (m.org(e) != kGhostVertex && m.dest(e) != kGhostVertex && m.link[e] != kNone)
        return triangle_of(m.link[e]);
    }
  }
  for (TriangleId t{0}; t < m.triangle_slots(); ++t)
    if (m.is_live(t) && !detail::is_ghost(m, t)) return t;
  return kNone;
}

}  // namespace

Location locate(const Mesh& mesh, Predicates& pred, const Point& p, EdgeRef hint) {
  TriangleId t = start_triangle(mesh, hint);
  if (t == kNone) return {};
  // A visibility walk in a Delaunay triangulation never revisits a triangle; twice the count (plus
  // slack) tolerates constrained meshes before giving up on the walk.
  const std::uint64_t limit = 2 * static_cast<std::uint64_t>(mesh.live_triangles()) + 64;
  SideChooser chooser;
  EdgeRef entered = kNone;
  for (std::uint64_t step = 0; step < limit; ++step) {
    double o[3];
    const unsigned first = chooser.first();
    EdgeRef exit = kNone;
    for (unsigned j = 0; j < 3 && exit == kNone; ++j) {
      const unsigned i = (first + j) % 3;
      const EdgeRef e = edge_of(t, i);
      o[i] = e == entered ? 1.0 : side_test(mesh, pred, e, p);  // entered from its far side
      if (o[i] < 0) exit = e;
    }
    if (exit == kNone) return classify(t, o);
    const EdgeRef across = mesh.link[exit];
    // Past a hull edge bordered by ghosts p is outside for certain (the hull is convex); past a
    // plain boundary edge the mesh may be non-convex, so only a scan can tell.
    if (across == kNone) return scan(mesh, pred, p, exit);
    t = triangle_of(across);
    if (detail::is_ghost(mesh, t)) return {LocateStatus::Outside, exit};
    entered = across;
  }
  return scan(mesh, pred, p, kNone);
}

}  // namespace deltri
