// The kernel's one Lawson routine, lawson(): flips until no stacked edge may be flipped. Which edges
// may flip is the caller's test (an incircle test, the tie-broken one, a half-plane test for ghost
// triangles, a lookup in a known cavity, "inside the recovered segment's cavity"); the flips are
// the kernel's flip (mesh/operations.h) in the caller's layout, so a fix to either is made once.
// Callers: flip_link below (vertex insertion, refinement), the constrained editor and segment
// recovery (mesh/constrained_editor.h, mesh/recover_edge.h), the Delaunay builders' tie pass
// (delaunay/lawson_pass.h), the parts' seams (mesh/parts.h).
#pragma once

#include <array>

#include "mesh/mesh.h"
#include "mesh/operations.h"
#include "util/small_vector.h"

namespace deltri {

// The flip stack: a vertex's link is short, so the common case needs no allocation (insertion
// runs once per Steiner point, and the allocator showed in refinement's profile).
using LawsonStack = SmallVector<EdgeRef, 64>;

// After flip<layout>(e) with twin f, the four outer edges of the quadrilateral, in the order each
// layout's callers have always stacked them (the order decides which of two cocircular diagonals
// survives, and so the output). The first and the last are the two edges opposite the old apex
// of e in the new triangles.
template <FlipLayout layout>
constexpr std::array<EdgeRef, 4> outer_edges(EdgeRef e, EdgeRef f) {
  if constexpr (layout == FlipLayout::Turn) return {lnext(e), lprev(e), lnext(f), lprev(f)};
  else return {e, lprev(e), f, lprev(f)};
}

// Where Lawson's flips spread: over the link of one vertex (an insertion: only the edges opposite
// the new vertex can stop being locally Delaunay) or to every edge a flip touches (a constraint
// was removed, or a whole triangulation is repaired).
enum class LawsonScope { Link, Everywhere };

// The kernel's one Lawson routine. Pops edges from `stack`; an edge that passes may_flip(e) is
// flipped in `layout` and flipped(e, f) is told (a caller's index follows the slots), then the
// outer edges of its quadrilateral are stacked: with Link scope only the two opposite v, and an
// edge popped whose apex is no longer v is skipped. may_flip must refuse boundary edges and
// subsegments and accept only edges whose quadrilateral is strictly convex (an incircle test does).
// Ends when the stack is empty: every flip lowers the lifted surface, so it does (Lawson).
// Returns the last flip's edge in e's slot (with Link scope and Turn, it leaves v), or kNone.
template <FlipLayout layout, LawsonScope scope, class Stack, class MayFlip, class Flipped>
EdgeRef lawson(Mesh& m, Stack& stack, VertexId v, MayFlip&& may_flip, Flipped&& flipped) {
  EdgeRef last = kNone;
  while (!stack.empty()) {
    const EdgeRef x = stack.back();
    stack.pop_back();
    if (scope == LawsonScope::Link && m.apex(x) != v) continue;
    if (!may_flip(x)) continue;
    const EdgeRef f = m.link[x];
    last = flip<layout>(m, x);
    flipped(x, f);
    const std::array<EdgeRef, 4> outer = outer_edges<layout>(x, f);
    if constexpr (scope == LawsonScope::Link) {
      stack.push_back(outer[0]);
      stack.push_back(outer[3]);
    } else {
      for (const EdgeRef o : outer) stack.push_back(o);
    }
  }
  return last;
}

// Lawson's flips on the link of v, where `out` leaves v: the edges opposite v in every triangle
// around it (the fan may be open at the boundary) are stacked, turning counter-clockwise from out
// and then clockwise, and lawson() runs with Link scope in the Turn layout. Returns the last
// flip's new edge (it left v when made), or kNone.
template <class MayFlip>
EdgeRef flip_link(Mesh& m, VertexId v, EdgeRef out, MayFlip&& may_flip) {
  LawsonStack stack;
  EdgeRef e = out;
  do {
    stack.push_back(lnext(e));
    e = m.link[lprev(e)];
  } while (e != kNone && e != out);
  if (e != out)
    for (EdgeRef s = m.link[out]; s != kNone; s = m.link[e]) {
      e = lnext(s);
      stack.push_back(lnext(e));
    }
  return lawson<FlipLayout::Turn, LawsonScope::Link>(m, stack, v, may_flip, [](EdgeRef, EdgeRef) {});
}

}  // namespace deltri
