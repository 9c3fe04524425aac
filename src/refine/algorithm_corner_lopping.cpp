#include "refine/algorithm_corner_lopping.h"

#include <algorithm>
#include <cmath>

#include "refine/refine.h"

namespace deltri {

CornerLopping::CornerLopping(const RefineOptions& opt) : apices_(opt.lopped_apices), sectors_(opt.lopped_sectors) {}

// t's angle at a lopped apex lies in a lopped sector (under 60 degrees, so the bisector is inside
// exactly when t is). The wider sectors at the same apex are meshed as anywhere else.
bool CornerLopping::in_lopped_corner(const Mesh& mesh, TriangleId t) const {
  if (sectors_ == nullptr) return false;
  const auto c = mesh.corners(t);
  for (int i = 0; i < 3; ++i) {
    if (!at_lopped_apex(c[i])) continue;
    const Point& o = mesh.point(c[i]);
    const Point& p = mesh.point(c[(i + 1) % 3]);
    const Point& q = mesh.point(c[(i + 2) % 3]);
    const double lp = std::hypot(p.x - o.x, p.y - o.y), lq = std::hypot(q.x - o.x, q.y - o.y);
    const double bx = (p.x - o.x) / lp + (q.x - o.x) / lq, by = (p.y - o.y) / lp + (q.y - o.y) / lq;
    const auto& sectors = *sectors_;
    auto s = std::lower_bound(sectors.begin(), sectors.end(), c[i], [](const auto& x, VertexId v) { return x[0] < v; });
    for (; s != sectors.end() && (*s)[0] == c[i]; ++s) {
      const Point& from = mesh.point((*s)[1]);
      const Point& to = mesh.point((*s)[2]);
      if ((from.x - o.x) * by - (from.y - o.y) * bx > 0.0 && bx * (to.y - o.y) - by * (to.x - o.x) > 0.0) return true;
    }
  }
  return false;
}

bool CornerLopping::at_lopped_apex(VertexId v) const {
  return apices_ && v < apices_->size() && (*apices_)[v] == 1;
}

bool CornerLopping::spoke(VertexId a, VertexId b) const {
  const auto kind = [&](VertexId v) { return v < apices_->size() ? (*apices_)[v] : 0; };
  return (kind(a) == 1 && kind(b) == 2) || (kind(a) == 2 && kind(b) == 1);
}

}  // namespace deltri
