// flip's invariant checks, in every build: this executable compiles src/mesh/operations.cpp
// itself with DELTRI_ASSERTS (tests/CMakeLists.txt), so its flip is the checked one even where the
// library is built without the checks (Release), and the test cannot compile to nothing.
#include <stdexcept>

#include "harness/check.h"
#include "harness/id_literals.h"
#include "mesh/mesh_checks.h"
#include "mesh/operations.h"

#if defined(NDEBUG) && !defined(DELTRI_ASSERTS)
#error "tests/mesh_checked needs the invariant checks on (DELTRI_ASSERTS)"
#endif

using namespace deltri;
using namespace meshcheck;

// flip's precondition is an invariant check (util/invariant.h): a boundary edge, or one carrying
// a subsegment, throws before anything is written.
TEST(flip_of_a_boundary_edge_or_a_subsegment_is_refused) {
  Mesh m = unit_square();
  const Mesh before = m;
  const auto refused = [&](EdgeRef e) {
    try {
      flip(m, e);
    } catch (const std::logic_error&) {
      return true;
    }
    return false;
  };
  CHECK(refused(find_edge(m, 0, 1)));  // on the boundary: no twin
  m.enable_subsegments();
  m.subsegments.push_back({0_v, 2_v, 1, 0});
  m.set_subsegment(find_edge(m, 0, 2), 0_s);
  const Mesh constrained = m;
  CHECK(refused(find_edge(m, 0, 2)));
  CHECK(refused(find_edge(m, 2, 0)));
  CHECK(triangle_set(m) == triangle_set(before));
  CHECK(m.link == constrained.link && m.subseg == constrained.subseg);
}

