#include "refine/encroached.h"

namespace deltri {

bool is_encroached(const Mesh& mesh, Predicates& pred, EdgeRef e, const EncroachRule& rule) {
  const Point& x = mesh.point(mesh.org(e));
  const Point& y = mesh.point(mesh.dest(e));
  if (encroaches(pred, x, y, mesh.point(mesh.apex(e)), rule)) return true;
  const EdgeRef twin = mesh.sym(e);
  return twin != kNone && encroaches(pred, x, y, mesh.point(mesh.apex(twin)), rule);
}

}  // namespace deltri
