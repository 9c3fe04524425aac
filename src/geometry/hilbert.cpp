#include "geometry/hilbert.h"

#include <algorithm>
#include <numeric>
#include <utility>

namespace deltri {
namespace {

std::uint32_t hilbert_index(std::uint32_t x, std::uint32_t y) {
  std::uint32_t d = 0;
  for (std::uint32_t s = 1u << 15; s > 0; s >>= 1) {
    const std::uint32_t rx = (x & s) ? 1 : 0, ry = (y & s) ? 1 : 0;
    d += s * s * ((rx * 3) ^ ry);
    if (ry == 0) {  // turn the lower-order quadrant so the curve stays continuous
      if (rx == 1) {
        x = ~x & 0xFFFFu;
        y = ~y & 0xFFFFu;
      }
      std::swap(x, y);
    }
  }
  return d;
}

}  // namespace

HilbertCurve::HilbertCurve(const Box& box) : lo_x_(box.lo_x), lo_y_(box.lo_y) {
  const double span = box.empty() ? 0.0 : std::max(box.width(), box.height());
  scale_ = span > 0 ? 65535.0 / span : 0.0;
}

std::uint32_t HilbertCurve::key(const Point& p) const {
  const auto cell = [this](double d) {
    const double c = d * scale_;
    return static_cast<std::uint32_t>(c > 0 ? std::min(65535.0, c) : 0.0);  // NaN and below: 0
  };
  return hilbert_index(cell(p.x - lo_x_), cell(p.y - lo_y_));
}

std::vector<std::uint32_t> hilbert_order(std::span<const Point> points) {
  Box box;
  for (const Point& p : points) box.add(p);
  const HilbertCurve curve(box);
  std::vector<std::uint32_t> keys(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) keys[i] = curve.key(points[i]);
  std::vector<std::uint32_t> order(points.size());
  std::iota(order.begin(), order.end(), 0u);
  std::sort(order.begin(), order.end(), [&keys](std::uint32_t a, std::uint32_t b) {
    return keys[a] != keys[b] ? keys[a] < keys[b] : a < b;
  });
  return order;
}

}  // namespace deltri
