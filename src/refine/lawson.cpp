#include "refine/lawson.h"

#include <vector>

#include "mesh/operations.h"
#include "refine/edge_finder.h"

namespace deltri {
namespace {

// Edge e has v as its apex; flip it when the triangle beyond has v strictly in its circumcircle.
bool must_flip(const Mesh& mesh, Predicates& pred, EdgeRef e) {
  const EdgeRef twin = mesh.link[e];
  if (twin == kNone || (mesh.has_subsegments() && mesh.subseg[e] != kNone)) return false;
  return pred.incircle(mesh.point(mesh.org(twin)), mesh.point(mesh.dest(twin)),
                       mesh.point(mesh.apex(twin)), mesh.point(mesh.apex(e))) > 0;
}

}  // namespace

EdgeRef restore_delaunay_around(Mesh& mesh, Predicates& pred, VertexId v, EdgeRef out) {
  std::vector<EdgeRef> stack;
  for_each_around(mesh, out, [&](EdgeRef e) { stack.push_back(lnext(e)); });
  EdgeRef leaving = out;
  while (!stack.empty()) {
    const EdgeRef e = stack.back();
    stack.pop_back();
    if (mesh.apex(e) != v || !must_flip(mesh, pred, e)) continue;
    const EdgeRef twin = mesh.link[e];
    const EdgeRef g = flip(mesh, e);  // v -> the far apex
    leaving = g;
    stack.push_back(lnext(g));
    stack.push_back(lprev(twin));
  }
  return mesh.org(leaving) == v ? leaving : out;
}

}  // namespace deltri
