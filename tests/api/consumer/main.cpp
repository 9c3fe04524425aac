// The C++ API from a CMake consumer (C++17): a unit square meshed with a 30 degree angle bound
// and an area bound, checked against facts that do not depend on deltri: the areas sum to 1,
// every triangle is counter-clockwise, within the area bound and no angle below 30 degrees;
// then a bad segment must throw deltri::Error naming it.
#include <cmath>
#include <cstdio>

#include <deltri/deltri.hpp>

int main() {
  deltri::Input in;
  in.points = {0, 0, 1, 0, 1, 1, 0, 1};
  in.segments = {1, 2, 2, 3, 3, 4, 4, 1};
  const deltri::Mesh m = deltri::triangulate(in, "pq30a0.01");
  double total = 0.0, smallest_angle = 180.0, largest_area = 0.0;
  for (int t = 0; t < m.triangle_count; ++t) {
    double p[3][2];
    for (int k = 0; k < 3; ++k)
      for (int c = 0; c < 2; ++c) p[k][c] = m.points[2 * (m.triangles[3 * t + k] - 1) + c];
    const double area = 0.5 * ((p[1][0] - p[0][0]) * (p[2][1] - p[0][1]) - (p[1][1] - p[0][1]) * (p[2][0] - p[0][0]));
    if (!(area > 0)) return std::printf("FAIL: triangle %d is not counter-clockwise\n", t), 1;
    total += area;
    largest_area = std::fmax(largest_area, area);
    for (int k = 0; k < 3; ++k) {
      const double* a = p[k];
      const double* b = p[(k + 1) % 3];
      const double* c = p[(k + 2) % 3];
      const double ux = b[0] - a[0], uy = b[1] - a[1], vx = c[0] - a[0], vy = c[1] - a[1];
      const double angle = std::atan2(std::fabs(ux * vy - uy * vx), ux * vx + uy * vy) * 180.0 / 3.14159265358979323846;
      smallest_angle = std::fmin(smallest_angle, angle);
    }
  }
  if (std::fabs(total - 1.0) > 1e-12 || largest_area > 0.01 || smallest_angle < 30.0 - 1e-9)
    return std::printf("FAIL: area sum %.17g, largest %.17g, smallest angle %.17g\n", total, largest_area, smallest_angle), 1;
  in.segments[1] = 9;
  try {
    deltri::triangulate(in, "p");
    return std::printf("FAIL: a segment to vertex 9 of 4 was accepted\n"), 1;
  } catch (const deltri::Error& e) {
    if (e.code() != DELTRI_INPUT_ERROR) return std::printf("FAIL: code %d for %s\n", e.code(), e.what()), 1;
    std::printf("ok: %d triangles, smallest angle %.2f, largest area %.5f; bad input: %s\n", m.triangle_count,
                smallest_angle, largest_area, e.what());
  }
  return 0;
}
