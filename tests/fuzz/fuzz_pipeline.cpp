// libFuzzer target over the whole pipeline, through run() (the library entry point the executable
// calls) with -C: the first byte picks the input kind (.poly or .node), the switches (-p, -pq,
// -pq -a) and the angle bound; the rest is the file. An input must either be rejected with an
// InputError or give a mesh that passes the consistency check; anything else traps. In builds
// without NDEBUG run() also checks the mesh after every stage and throws on a fault.
//
// Inputs are kept small so that an execution stays fast: at most 200 vertices, 400 segments, 20
// holes and regions. The -a bound is derived from the bounding box (about 200 triangles' worth),
// so that a tiny area never legitimately asks for millions of triangles; and -S4000 caps the
// Steiner points, because a valid input such as a 0.1-wide spike 2e8 long needs billions of
// quality triangles (the first finding, a timeout that was no bug). A hang that remains is a loop
// that inserts nothing.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "cli/run.h"
#include "options/switches.h"
#include "fuzz_common.h"
#include "io/node_file.h"
#include "io/poly_file.h"
#include "util/errors.h"

namespace {

using namespace deltri;

bool small_enough(const Pslg& p) {
  return p.points.size() <= 200 && p.segments.size() <= 400 && p.holes.size() <= 20 && p.regions.size() <= 20 &&
         p.num_attributes <= 4;
}

// A maximum area of about 1/200 of the bounding box, or 0 when the box has no usable area.
double area_bound(const Pslg& p) {
  double x0 = p.points[0].x, x1 = x0, y0 = p.points[0].y, y1 = y0;
  for (const Point& q : p.points) {
    x0 = std::min(x0, q.x), x1 = std::max(x1, q.x);
    y0 = std::min(y0, q.y), y1 = std::max(y1, q.y);
  }
  const double a = (x1 - x0) * (y1 - y0) / 200.0;
  return std::isnormal(a) ? a : 0.0;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::uint8_t mode = 0;
  if (!fuzz::take_selector(data, size, mode)) return -1;
  const bool poly = (mode & 1) == 0;
  const int work = (mode >> 1) % 3;             // 0: -p, 1: -pq, 2: -pq -a
  static const char* const angles[] = {"", "25", "30", "33"};
  const char* angle = angles[(mode >> 3) & 3];

  // The readers are fuzzed on their own; here they only decide whether the input is small.
  const std::string path = fuzz::write_input(poly ? "p/in.poly" : "n/in.node", data, size);
  Pslg pslg;
  try {
    pslg = poly ? read_poly_file(path) : read_node_file(path);
  } catch (const InputError&) {
    return 0;
  } catch (...) {
    __builtin_trap();
  }
  if (!small_enough(pslg)) return -1;

  std::string sw = poly ? "-pCQS4000" : "-CQS4000";
  if (work >= 1) sw += std::string("q") + angle;
  if (work == 2) {
    const double a = area_bound(pslg);
    if (a > 0) {
      char buf[40];
      std::snprintf(buf, sizeof buf, "a%.17g", a);
      sw += buf;
    }
  }
  const char* argv[] = {"deltri", sw.c_str(), path.c_str()};
  try {
    const Switches switches = parse_switches(3, argv);
    const int status = run(switches);
    if (status != kExitOk) __builtin_trap();  // kExitCheck: -C found a fault
  } catch (const InputError&) {
  } catch (...) {
    __builtin_trap();  // UsageError (our own switches), OutputError, internal errors
  }
  return 0;
}
