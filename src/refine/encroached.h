// Is a subsegment encroached? Shewchuk 2001, Appendix A and Fig. 41: in a constrained Delaunay
// triangulation only the one or two apices opposite a subsegment need testing, because any
// visible vertex inside its diametral circle or lens would sit inside one of those triangles'
// circumcircles. The test itself, and its boundary rule, is geometry/encroachment.h's.
#pragma once

#include "geometry/encroachment.h"
#include "geometry/predicates.h"
#include "mesh/mesh.h"

namespace deltri {

// Fig. 38 l.4: is the subsegment on edge e encroached by the apex on either side?
bool is_encroached(const Mesh& mesh, Predicates& pred, EdgeRef e, const EncroachRule& rule);

}  // namespace deltri
