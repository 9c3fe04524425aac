#include "delaunay/lawson_pass.h"

#include <vector>

#include "mesh/lawson.h"

namespace deltri {

void lawson_pass(Mesh& mesh, Predicates& pred) {
  std::vector<EdgeRef> stack;
  for (EdgeRef e{0}; e < mesh.corner.size(); ++e)
    if (mesh.link[e] != kNone && mesh.link[e] > e) stack.push_back(e);
  // A far vertex inside (or, by the tie rule, on) the circle makes a convex quadrilateral, so
  // the flip is valid; each flip lowers the perturbed lifted surface, so the loop ends.
  const auto may_flip = [&](EdgeRef e) {
    const EdgeRef f = mesh.link[e];
    return f != kNone && pred.incircle_perturbed(mesh.point(mesh.org(e)), mesh.point(mesh.dest(e)),
                                                 mesh.point(mesh.apex(e)), mesh.point(mesh.apex(f))) > 0;
  };
  lawson<FlipLayout::Turn, LawsonScope::Everywhere>(mesh, stack, kNone, may_flip, [](EdgeRef, EdgeRef) {});
}

}  // namespace deltri
