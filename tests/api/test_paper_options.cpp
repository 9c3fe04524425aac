// The library takes --range-restricted and --corner-lopping after the letters, as the command line
// does, and refuses the combinations the command line refuses with an error status, never exiting:
//   test_api_paper_options
// A 20-degree wedge: with --corner-lopping the mesh has more vertices than the input's three (the
// shield's), its segments are the input's three, split (two end at the lopped apex and one joins
// the other two: no shield edge among them); -pYq with it is a usage error.
#include "deltri/deltri.hpp"

#include <cmath>
#include <cstdio>

int main() {
  deltri::api::Input in;
  in.points = {0, 0, 10, 0, 9, 3.2};
  in.segments = {1, 2, 2, 3, 3, 1};
  int failures = 0;
  const deltri::api::Mesh plain = deltri::api::triangulate(in, "pq20");
  const deltri::api::Mesh lopped = deltri::api::triangulate(in, "pq20 --corner-lopping");
  const deltri::api::Mesh ranged = deltri::api::triangulate(in, "pq20a1 --range-restricted");
  if (lopped.point_count <= plain.point_count) {
    std::printf("FAIL: --corner-lopping: %d points, no more than without it (%d)\n", lopped.point_count, plain.point_count);
    ++failures;
  }
  // Every output segment lies on an input side: its ends are collinear with one of the three.
  for (int s = 0; s < lopped.segment_count; ++s) {
    const double* p = &lopped.points[2 * (lopped.segments[2 * s] - 1)];
    const double* q = &lopped.points[2 * (lopped.segments[2 * s + 1] - 1)];
    bool on_side = false;
    for (int k = 0; k < 3; ++k) {
      const double* a = &in.points[2 * k];
      const double* b = &in.points[2 * ((k + 1) % 3)];
      const auto off = [&](const double* r) { return std::abs((b[0] - a[0]) * (r[1] - a[1]) - (b[1] - a[1]) * (r[0] - a[0])); };
      on_side = on_side || (off(p) < 1e-9 && off(q) < 1e-9);
    }
    if (!on_side) {
      std::printf("FAIL: --corner-lopping: output segment %d is not on an input segment (a shield edge?)\n", s + 1);
      ++failures;
    }
  }
  if (ranged.triangle_count == 0) {
    std::printf("FAIL: --range-restricted: no triangles\n");
    ++failures;
  }
  try {
    (void)deltri::api::triangulate(in, "pYq --corner-lopping");
    std::printf("FAIL: -pYq --corner-lopping was accepted\n");
    ++failures;
  } catch (const deltri::api::Error& e) {
    std::printf("-pYq --corner-lopping refused (code %d): %s\n", e.code(), e.what());
  }
  if (failures) return 1;
  std::printf("--corner-lopping: %d points, %d triangles, %d segments; --range-restricted: %d triangles\n",
              lopped.point_count, lopped.triangle_count, lopped.segment_count, ranged.triangle_count);
  return 0;
}
