#include "cdt/convex_hull.h"

namespace deltri {

std::size_t enclose_convex_hull(Mesh& mesh) {
  mesh.enable_subsegments();
  std::size_t added = 0;
  for (EdgeRef e = 0; e < mesh.corner.size(); ++e) {
    if (mesh.corner[e] == kNone || mesh.link[e] != kNone || mesh.subseg[e] != kNone) continue;
    mesh.subsegments.push_back({mesh.org(e), mesh.dest(e), 1, kNone});
    mesh.set_subsegment(e, static_cast<SubsegmentId>(mesh.subsegments.size() - 1));
    ++added;
  }
  return added;
}

}  // namespace deltri
