#include "mesh/star.h"

namespace deltri {

bool gather_star(const Mesh& m, EdgeRef first, Star& star) {
  star.out.clear();
  star.ring.clear();
  EdgeRef e = first;
  do {
    if (m.has_subsegments() && m.subseg.has(e)) return false;
    star.out.push_back(e);
    star.ring.push_back(m.dest(e));
    e = m.onext(e);
    if (e == kNone) return false;
  } while (e != first);
  star.ring.push_back(star.ring.front());
  return star.out.size() >= 3;
}

}  // namespace deltri
