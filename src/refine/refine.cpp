#include "refine/refine.h"

#include "refine/halves.h"
#include "refine/terminator.h"

namespace deltri {

RefineReport refine_mesh(Mesh& mesh, Predicates& pred, const RefineOptions& opt) {
  if (halves_apply(mesh, opt)) return refine_in_halves(mesh, pred, opt);
  Terminator terminator(mesh, pred, opt);
  return terminator.run();
}

}  // namespace deltri
