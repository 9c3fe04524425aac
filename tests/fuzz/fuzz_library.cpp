// libFuzzer target over the C library entry (deltri_triangulate and deltri_triangulate_sized): a
// fuzzed switch string and fuzzed arrays. The call must return OK, an input, usage or memory error
// with a one-line message, and never a check failure or an internal error (the switches always
// carry C, so a bad mesh is a check failure); every array it allocates is released (the leak check
// catches one it forgets or one it shares with the input).
//
// Layout: a byte L, then L bytes of switch text (S removed: the target caps the Steiner points at
// 2000 so that a tiny a or a q near the limit never asks for millions of triangles), then counts
// (points, attributes, segments, holes, regions, triangles, flags), then each number from a byte
// (a small whole or half value) or, when that byte is 255, from the next 8 raw bytes (NaN,
// infinities, subnormals, huge values).
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "deltri/triangle.h"

namespace {

struct Bytes {
  const std::uint8_t* p;
  std::size_t n;
  std::uint8_t byte() {
    if (n == 0) return 0;
    --n;
    return *p++;
  }
  double real() {
    const std::uint8_t b = byte();
    if (b != 255 || n < 8) return (static_cast<double>(b) - 100.0) / 2.0;
    double d;
    std::memcpy(&d, p, 8);
    p += 8, n -= 8;
    return d;
  }
  int index() { return static_cast<int>(byte()) - 2; }  // -2 .. 253: out-of-range numbers included
};

int big_enough(const double*, const double*, const double*, double area, void* user) {
  return area > *static_cast<double*>(user);
}

void release(triangulateio& o) {
  for (void* p : {static_cast<void*>(o.pointlist), static_cast<void*>(o.pointattributelist),
                  static_cast<void*>(o.pointmarkerlist), static_cast<void*>(o.trianglelist),
                  static_cast<void*>(o.triangleattributelist), static_cast<void*>(o.neighborlist),
                  static_cast<void*>(o.segmentlist), static_cast<void*>(o.segmentmarkerlist),
                  static_cast<void*>(o.edgelist), static_cast<void*>(o.edgemarkerlist), static_cast<void*>(o.normlist)})
    trifree(p);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1 || size > 8192) return -1;
  Bytes in{data, size};
  const std::size_t length = in.byte() % 40;
  std::string text;
  for (std::size_t i = 0; i < length && in.n; ++i) {
    const char c = static_cast<char>(in.byte());
    if (c != 'S' && c != '\0') text += c;
  }
  if (!text.empty() && text[0] == '-' && text.rfind("--", 0) != 0) text.erase(0, 1);
  // Text that would continue the cap's number ("57", ".5e9") is dropped: S200057 asked 100 times the
  // work the cap allows, and such runs timed out in this build (F16).
  text.erase(0, text.find_first_not_of("0123456789.eE"));
  const std::string switches = "CQS2000" + text;

  const int points = in.byte() % 40, attributes = in.byte() % 3, segments = in.byte() % 40;
  const int holes = in.byte() % 4, regions = in.byte() % 4, triangles = in.byte() % 16;
  const std::uint8_t flags = in.byte();
  std::vector<double> xy, attr, hole, region, area;
  std::vector<int> pmark, seg, smark, tri;
  for (int i = 0; i < 2 * points; ++i) xy.push_back(in.real());
  for (int i = 0; i < attributes * points; ++i) attr.push_back(in.real());
  if (flags & 1)
    for (int i = 0; i < points; ++i) pmark.push_back(in.index());
  for (int i = 0; i < 2 * segments; ++i) seg.push_back(in.index());
  if (flags & 2)
    for (int i = 0; i < segments; ++i) smark.push_back(in.index());
  for (int i = 0; i < 2 * holes; ++i) hole.push_back(in.real());
  for (int i = 0; i < 4 * regions; ++i) region.push_back(in.real());
  const int corners = flags & 4 ? 6 : 3;
  for (int i = 0; i < corners * triangles; ++i) tri.push_back(in.index());
  if (flags & 8)
    for (int i = 0; i < triangles; ++i) area.push_back(in.real());

  auto data_of = [](auto& v) { return v.empty() ? nullptr : v.data(); };
  triangulateio input{};
  input.pointlist = data_of(xy);
  input.pointattributelist = data_of(attr);
  input.pointmarkerlist = data_of(pmark);
  input.numberofpoints = points;
  input.numberofpointattributes = attributes;
  input.segmentlist = data_of(seg);
  input.segmentmarkerlist = data_of(smark);
  input.numberofsegments = segments;
  input.holelist = data_of(hole);
  input.numberofholes = holes;
  input.regionlist = data_of(region);
  input.numberofregions = regions;
  input.trianglelist = data_of(tri);
  input.numberoftriangles = triangles;
  input.numberofcorners = corners;
  input.trianglearealist = data_of(area);

  triangulateio out{}, vor{};
  deltri_status status{};
  double limit = 1.0 + (flags >> 4);
  const int code = flags & 16 ? deltri_triangulate_sized(switches.c_str(), &input, &out, &vor, big_enough, &limit, &status)
                              : deltri_triangulate(switches.c_str(), &input, &out, &vor, &status);
#ifdef DELTRI_FUZZ_PRINT
  std::fprintf(stderr, "switches '%s': code %d: %s\n", switches.c_str(), code, status.message);
#endif
  if (code != status.code) __builtin_trap();
  const std::size_t message = strnlen(status.message, sizeof status.message);
  if (message == sizeof status.message || std::strchr(status.message, '\n')) __builtin_trap();
  switch (code) {
    case DELTRI_OK:
      if (message != 0) __builtin_trap();
      break;
    case DELTRI_INPUT_ERROR:
    case DELTRI_USAGE_ERROR:
    case DELTRI_MEMORY_ERROR:
      if (message == 0) __builtin_trap();
      break;
    default:
      __builtin_trap();  // a check failure or an internal error is a bug
  }
  release(out);
  release(vor);
  return 0;
}
