// The Terminator's use of vertex relocation (relocation.h) in the second stage of locally optimal points.
#include "refine/terminator.h"

namespace deltri {

// Moves t's free corners, one after the other, to raise their stars' measure under `goal`
// (relocation.h), the stars' triangles going back in the queue, until t is good; true when one
// moved. Moves add no vertex, so the Steiner cap does not bound them: kRelocationsPerVertex does.
bool Terminator::move_corners(TriangleId t, StarGoal goal) {
  bool moved = false;
  for (unsigned k = 0; k < 3; ++k) {
    const EdgeRef e = edge_of(t, k);
    if (mesh_.kind[mesh_.org(e)] != VertexKind::Free) continue;
    if (relocations_ >= static_cast<std::uint64_t>(kRelocationsPerVertex * mesh_.vertex_count())) return moved;
    if (!relocator_.relocate(mesh_, pred_, policy_.rule, e, goal)) continue;
    ++relocations_;
    moved = true;
    for (const EdgeRef s : relocator_.star_edges()) enqueue_if_bad(triangle_of(s));
    if (!assess(t).bad()) return moved;  // the rest of t's corners need not move
  }
  return moved;
}

// Above the off-centres' reach (the second stage, with locally optimal points), a bad triangle's
// free corners first move where their stars' smallest angles are larger; a triangle that meets the
// bound then needs no new vertex. Once t meets the bound its other corners stay: their searches
// were most of the second stage's time and the moves they made gained nothing measurable
// (docs/refinement.md).
bool Terminator::relocate_corners(TriangleId t) {
  return optimal_points_ && opt_.angle.cascades() && move_corners(t, {});
}

// A triangle bad only for an angle above --max-angle whose point or subsegment split the guard
// refused (norway.poly: a 103-degree triangle over a subsegment 1.7 times the floor, which no split
// can halve above it): its free corners move instead where their stars' least margin against both
// angle bounds rises (StarGoal), which opens the obtuse corner without a shorter edge. A move makes
// no star worse.
void Terminator::open_obtuse_corner(TriangleId t, const Assessment& a) {
  if (!a.too_obtuse || a.skinny || a.too_large) return;
  const Criteria& rules = rules_for(t);
  move_corners(t, {&rules.angle, &rules.max_angle});
}

Outcome Terminator::refused_for(TriangleId t, const Assessment& a, Outcome refusal) {
  if (refusal == Outcome::BelowFloor) open_obtuse_corner(t, a);
  return refusal;
}

}  // namespace deltri
