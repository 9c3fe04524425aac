#include "cdt/subsegment_table.h"

#include <vector>

namespace deltri {

void drop_dead_subsegments(Mesh& mesh) {
  std::vector<SubsegmentId> renumber(mesh.subsegments.size(), kNone);
  SubsegmentId next = 0;
  for (SubsegmentId s = 0; s < mesh.subsegments.size(); ++s) {
    if (mesh.subsegments[s].a == kNone) continue;
    renumber[s] = next;
    mesh.subsegments[next++] = mesh.subsegments[s];
  }
  if (next == mesh.subsegments.size()) return;
  mesh.subsegments.resize(next);
  for (SubsegmentId& s : mesh.subseg)
    if (s != kNone) s = renumber[s];
}

}  // namespace deltri
