// Deterministic random inputs and ulp nudging shared by the geometry tests.
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>

#include "geometry/point.h"

namespace testing_support {

class Random {
 public:
  explicit Random(std::uint64_t seed) : engine_(seed) {}
  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(engine_); }
  int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(engine_); }
  deltri::Point point(double lo, double hi) { return {uniform(lo, hi), uniform(lo, hi)}; }

 private:
  std::mt19937_64 engine_;
};

// x moved by |steps| representable doubles, up if steps > 0.
inline double nudge(double x, int steps) {
  const double toward = steps > 0 ? std::numeric_limits<double>::infinity()
                                  : -std::numeric_limits<double>::infinity();
  for (int i = 0; i < std::abs(steps); ++i) x = std::nextafter(x, toward);
  return x;
}

inline deltri::Point nudge(const deltri::Point& p, int dx, int dy) { return {nudge(p.x, dx), nudge(p.y, dy)}; }

inline int sign_of(double v) { return v > 0.0 ? 1 : (v < 0.0 ? -1 : 0); }

}  // namespace testing_support
