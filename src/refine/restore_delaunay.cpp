#include "refine/restore_delaunay.h"


#include "mesh/lawson.h"
#include "mesh/operations.h"
#include "refine/edge_finder.h"
#include "util/invariant.h"

namespace deltri {
namespace {

// Edge e has v as its apex; flip it when the triangle beyond has v strictly in its circumcircle.
bool must_flip(const Mesh& mesh, Predicates& pred, EdgeRef e) {
  const EdgeRef twin = mesh.link[e];
  if (twin == kNone || (mesh.has_subsegments() && mesh.subseg.has(e))) return false;
  return pred.incircle(mesh.point(mesh.org(twin)), mesh.point(mesh.dest(twin)),
                       mesh.point(mesh.apex(twin)), mesh.point(mesh.apex(e))) > 0;
}

// Lawson's flips on the link of v (the edges opposite it), as after an exact insertion.
EdgeRef flip_link_of(Mesh& mesh, Predicates& pred, VertexId v, EdgeRef out) {
  const EdgeRef last = flip_link(mesh, v, out, [&](EdgeRef e) { return must_flip(mesh, pred, e); });
  return last != kNone && mesh.org(last) == v ? last : out;
}

// A spoke v -> x that is not locally Delaunay, or kNone. Only a rounded v can have one: v then
// lies a little off the line of the subsegment it split, and the spoke to an apex of that
// subsegment can see the split's other end inside its circumcircle (a fuzzed thin wedge did).
EdgeRef bad_spoke(const Mesh& mesh, Predicates& pred, EdgeRef out) {
  EdgeRef found = kNone;
  for_each_around(mesh, out, [&](EdgeRef e) {
    if (found != kNone || !must_flip(mesh, pred, e)) return;
    const EdgeRef twin = mesh.link[e];
    const Point& c = mesh.point(mesh.apex(e));
    const Point& d = mesh.point(mesh.apex(twin));
    // The flip must leave two counter-clockwise triangles (Lawson's lemma promises it; checked).
    if (pred.orient2d(c, d, mesh.point(mesh.dest(e))) > 0 && pred.orient2d(d, c, mesh.point(mesh.org(e))) > 0)
      found = e;
  });
  return found;
}

// The check behind exactly_on, made in builds with invariant checks only: its predicate calls are
// not counted, so -V reports the same counts in every build (docs/manual.md's -V example).
[[maybe_unused]] bool link_flips_sufficed(const Mesh& mesh, Predicates& pred, EdgeRef leaving) {
  const UncountedCalls uncounted(pred);
  return bad_spoke(mesh, pred, leaving) == kNone;
}

}  // namespace

EdgeRef restore_delaunay_around(Mesh& mesh, Predicates& pred, VertexId v, EdgeRef out, bool exactly_on) {
  EdgeRef leaving = flip_link_of(mesh, pred, v, out);
  if (exactly_on) {
    DELTRI_ASSERT(link_flips_sufficed(mesh, pred, leaving));
    return leaving;
  }
  // Each flip removes a locally non-Delaunay edge, so the loop ends (Lawson).
  for (EdgeRef spoke = bad_spoke(mesh, pred, leaving); spoke != kNone; spoke = bad_spoke(mesh, pred, leaving)) {
    const EdgeRef g = flip(mesh, spoke);       // apex -> far apex; its twin's triangle keeps v
    leaving = flip_link_of(mesh, pred, v, lprev(mesh.link[g]));
  }
  return leaving;
}

}  // namespace deltri
