// libFuzzer target over the text readers. The first byte picks the reader (and for .ele the
// numbering and vertex count); the rest is the file. Every input must either be read or be
// rejected with an InputError; what is read must satisfy the invariants the later stages rely
// on (checked here independently of the readers' own code).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <string>

#include "fuzz_common.h"
#include "io/area_file.h"
#include "io/ele_file.h"
#include "io/node_file.h"
#include "io/poly_file.h"
#include "util/errors.h"

namespace {

using namespace deltri;

void require(bool ok) {
  if (!ok) __builtin_trap();
}

void check_pslg(const Pslg& p, bool poly) {
  // A .poly with zero vertices reads in.node beside it, which never exists here.
  require(p.points.size() >= 3);
  require(p.first_index == 0 || p.first_index == 1);
  for (const Point& q : p.points) require(std::isfinite(q.x) && std::isfinite(q.y));
  require(p.num_attributes >= 0);
  require(p.attributes.size() == p.points.size() * static_cast<std::size_t>(p.num_attributes));
  for (double a : p.attributes) require(std::isfinite(a));
  require(p.has_markers ? p.markers.size() == p.points.size() : p.markers.empty());
  if (!poly) {
    require(p.segments.empty() && p.holes.empty() && p.regions.empty());
    return;
  }
  for (const Pslg::Segment& s : p.segments) require(s.a < p.points.size() && s.b < p.points.size());
  for (const Point& h : p.holes) require(std::isfinite(h.x) && std::isfinite(h.y));
  for (const Pslg::Region& r : p.regions)
    require(std::isfinite(r.at.x) && std::isfinite(r.at.y) && std::isfinite(r.attribute) && std::isfinite(r.max_area));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::uint8_t mode = 0;
  if (!fuzz::take_selector(data, size, mode)) return -1;
  try {
    switch (mode % 4) {
      case 0: check_pslg(read_node_file(fuzz::write_input("in.node", data, size)), false); break;
      case 1: check_pslg(read_poly_file(fuzz::write_input("in.poly", data, size)), true); break;
      case 2: {
        const int first = (mode >> 2) & 1;
        const std::uint32_t vertices = 3u + (mode >> 3);
        const EleData ele = read_ele_file(fuzz::write_input("in.ele", data, size), first, vertices);
        require(ele.nodes_per_triangle == 3 || ele.nodes_per_triangle == 6);
        require(ele.corners.size() % ele.nodes_per_triangle == 0);
        for (std::uint32_t c : ele.corners) require(c < vertices);
        require(ele.num_attributes >= 0);
        require(ele.attributes.size() == ele.triangle_count() * static_cast<std::size_t>(ele.num_attributes));
        for (double a : ele.attributes) require(std::isfinite(a));
        break;
      }
      default: {
        const std::uint32_t expected = (mode >> 2) & 1 ? 0xFFFFFFFFu : (mode >> 3);
        const std::vector<double> areas = read_area_file(fuzz::write_input("in.area", data, size), expected);
        if (expected != 0xFFFFFFFFu) require(areas.size() == expected);
        for (double a : areas) require(std::isfinite(a));
        break;
      }
    }
  } catch (const InputError&) {
    // The documented way to reject a file.
  } catch (...) {
    __builtin_trap();  // anything else (bad_alloc on a tiny file, logic_error, ...) is a bug
  }
  return 0;
}
