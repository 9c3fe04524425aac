#include "delaunay/lawson_pass.h"

#include <vector>

#include "mesh/operations.h"

namespace deltri {

void lawson_pass(Mesh& mesh, Predicates& pred) {
  std::vector<EdgeRef> stack;
  for (EdgeRef e = 0; e < mesh.corner.size(); ++e)
    if (mesh.link[e] != kNone && mesh.link[e] > e) stack.push_back(e);
  while (!stack.empty()) {
    const EdgeRef e = stack.back();
    stack.pop_back();
    const EdgeRef f = mesh.link[e];
    if (f == kNone) continue;
    // A far vertex inside (or, by the tie rule, on) the circle makes a convex quadrilateral, so
    // the flip is valid; each flip lowers the perturbed lifted surface, so the loop ends.
    if (pred.incircle_perturbed(mesh.point(mesh.org(e)), mesh.point(mesh.dest(e)), mesh.point(mesh.apex(e)),
                                mesh.point(mesh.apex(f))) <= 0)
      continue;
    const EdgeRef g = flip(mesh, e);
    const EdgeRef h = mesh.link[g];
    for (const EdgeRef x : {lnext(g), lprev(g), lnext(h), lprev(h)}) stack.push_back(x);
  }
}

}  // namespace deltri
