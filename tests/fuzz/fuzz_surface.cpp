// libFuzzer target over the facet readers (TetGen's .poly with a 3-D node section, and .smesh) and,
// for small inputs, the surface mode behind them. The first byte picks the format (bit 0) and what
// follows the read (bits 1-2: nothing, -p, -pq25, -pq30, each with -C and -S500). A file must be
// read or rejected with an InputError; what is read must satisfy the invariants the mesher relies
// on (checked here independently of the reader); a run must exit 0 with -C passing, or reject the
// input with an InputError. Anything else traps.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>

#include "cli/run.h"
#include "cli/surface_run.h"
#include "options/switches.h"
#include "fuzz_common.h"
#include "io/facet_file.h"
#include "util/errors.h"

namespace {

using namespace deltri;

void require(bool ok) {
  if (!ok) __builtin_trap();
}

std::size_t check_facets(const FacetInput& f) {
  require(f.first_index == 0 || f.first_index == 1);
  for (const Point3& p : f.points) require(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z));
  require(f.has_markers ? f.markers.size() == f.points.size() : f.markers.empty());
  std::size_t corners = 0;
  for (const FacetInput::Facet& facet : f.facets) {
    for (const auto& polygon : facet.polygons) {
      require(!polygon.empty());
      for (std::uint32_t v : polygon) require(v < f.points.size());
      corners += polygon.size();
    }
    for (const Point3& h : facet.holes) require(std::isfinite(h.x) && std::isfinite(h.y) && std::isfinite(h.z));
    require(facet.hole_lines.empty() || facet.hole_lines.size() == facet.holes.size());
  }
  return corners;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::uint8_t mode = 0;
  if (!fuzz::take_selector(data, size, mode)) return -1;
  const bool smesh = mode & 1;
  const int work = (mode >> 1) & 3;
  const std::string path = fuzz::write_input(smesh ? "s/in.smesh" : "s/in.poly", data, size);
  std::size_t corners = 0, points = 0;
  try {
    const FacetInput input = read_facet_file(path, 1);
    corners = check_facets(input);
    points = input.points.size();
  } catch (const InputError&) {
    return 0;  // the documented way to reject a file
  } catch (...) {
    __builtin_trap();
  }
  if (work == 0 || points > 100 || corners > 400) return 0;
  static const char* const switches[] = {"", "-pCQS500", "-pCQS500q25", "-pCQS500q30"};
  const char* argv[] = {"deltri", switches[work], path.c_str()};
  try {
    const Switches sw = parse_switches(3, argv);
    if (run_surface(sw, path) != kExitOk) __builtin_trap();  // -C found a fault, or an output failed
  } catch (const InputError&) {
  } catch (...) {
    __builtin_trap();
  }
  return 0;
}
