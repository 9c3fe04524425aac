#include "refine/refine.h"

#include "refine/terminator.h"

namespace deltri {

RefineReport refine_mesh(Mesh& mesh, Predicates& pred, const RefineOptions& opt) {
  Terminator terminator(mesh, pred, opt);
  return terminator.run();
}

}  // namespace deltri
