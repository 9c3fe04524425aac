// An independent exact evaluator for the geometry tests: dyadic rationals m * 2^e with an
// arbitrary-precision integer m (32-bit limbs). Every double converts exactly, and sums and
// products are exact, so the determinants below are the true ones, computed in a way that shares
// nothing with the expansion arithmetic under test (and uses different, but equivalent, formulas).
// Slow, and meant to be.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "geometry/point.h"

namespace reference {

class BigInt {
 public:
  BigInt() = default;
  explicit BigInt(std::int64_t v) : negative_(v < 0) {
    std::uint64_t mag = v < 0 ? std::uint64_t(0) - std::uint64_t(v) : std::uint64_t(v);
    while (mag != 0) {
      limbs_.push_back(std::uint32_t(mag));
      mag >>= 32;
    }
  }

  int sign() const { return limbs_.empty() ? 0 : (negative_ ? -1 : 1); }
  bool is_zero() const { return limbs_.empty(); }

  // The value times 2^shift, to double precision (from the top three limbs).
  double approximate(int shift) const {
    double v = 0.0;
    const std::size_t n = limbs_.size();
    for (std::size_t i = n > 3 ? n - 3 : 0; i < n; ++i) {
      v += std::ldexp(static_cast<double>(limbs_[i]), static_cast<int>(32 * i) + shift);
    }
    return negative_ ? -v : v;
  }

  BigInt shifted_left(int bits) const {
    if (is_zero() || bits == 0) return *this;
    BigInt r;
    r.negative_ = negative_;
    const int words = bits / 32, rem = bits % 32;
    r.limbs_.assign(words, 0);
    std::uint32_t carry = 0;
    for (std::uint32_t limb : limbs_) {
      r.limbs_.push_back(rem == 0 ? limb : (limb << rem) | carry);
      carry = rem == 0 ? 0 : limb >> (32 - rem);
    }
    if (carry != 0) r.limbs_.push_back(carry);
    return r;
  }

  BigInt operator-() const {
    BigInt r = *this;
    if (!r.is_zero()) r.negative_ = !r.negative_;
    return r;
  }

  friend BigInt operator+(const BigInt& a, const BigInt& b) {
    if (a.negative_ == b.negative_) {
      BigInt r;
      r.negative_ = a.negative_;
      r.limbs_ = add_magnitudes(a.limbs_, b.limbs_);
      return r;
    }
    const int cmp = compare_magnitudes(a.limbs_, b.limbs_);
    if (cmp == 0) return BigInt();
    const BigInt& big = cmp > 0 ? a : b;
    const BigInt& small = cmp > 0 ? b : a;
    BigInt r;
    r.negative_ = big.negative_;
    r.limbs_ = subtract_magnitudes(big.limbs_, small.limbs_);
    return r;
  }

  friend BigInt operator-(const BigInt& a, const BigInt& b) { return a + (-b); }

  friend BigInt operator*(const BigInt& a, const BigInt& b) {
    if (a.is_zero() || b.is_zero()) return BigInt();
    std::vector<std::uint64_t> acc(a.limbs_.size() + b.limbs_.size() + 1, 0);
    for (std::size_t i = 0; i < a.limbs_.size(); ++i) {
      std::uint64_t carry = 0;
      for (std::size_t j = 0; j < b.limbs_.size(); ++j) {
        const std::uint64_t t = acc[i + j] + std::uint64_t(a.limbs_[i]) * b.limbs_[j] + carry;
        acc[i + j] = t & 0xffffffffu;
        carry = t >> 32;
      }
      std::size_t k = i + b.limbs_.size();
      while (carry != 0) {
        const std::uint64_t t = acc[k] + carry;
        acc[k++] = t & 0xffffffffu;
        carry = t >> 32;
      }
    }
    BigInt r;
    r.negative_ = a.negative_ != b.negative_;
    for (std::uint64_t v : acc) r.limbs_.push_back(std::uint32_t(v));
    r.trim();
    return r;
  }

 private:
  using Limbs = std::vector<std::uint32_t>;

  void trim() {
    while (!limbs_.empty() && limbs_.back() == 0) limbs_.pop_back();
    if (limbs_.empty()) negative_ = false;
  }

  static int compare_magnitudes(const Limbs& a, const Limbs& b) {
    if (a.size() != b.size()) return a.size() < b.size() ? -1 : 1;
    for (std::size_t i = a.size(); i-- > 0;) {
      if (a[i] != b[i]) return a[i] < b[i] ? -1 : 1;
    }
    return 0;
  }

  static Limbs add_magnitudes(const Limbs& a, const Limbs& b) {
    Limbs r;
    std::uint64_t carry = 0;
    for (std::size_t i = 0; i < std::max(a.size(), b.size()); ++i) {
      const std::uint64_t t = carry + (i < a.size() ? a[i] : 0u) + (i < b.size() ? b[i] : 0u);
      r.push_back(std::uint32_t(t));
      carry = t >> 32;
    }
    if (carry != 0) r.push_back(std::uint32_t(carry));
    return r;
  }

  // Requires |a| > |b|.
  static Limbs subtract_magnitudes(const Limbs& a, const Limbs& b) {
    Limbs r;
    std::int64_t borrow = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
      std::int64_t t = std::int64_t(a[i]) - borrow - (i < b.size() ? std::int64_t(b[i]) : 0);
      borrow = t < 0 ? 1 : 0;
      if (t < 0) t += std::int64_t(1) << 32;
      r.push_back(std::uint32_t(t));
    }
    while (!r.empty() && r.back() == 0) r.pop_back();
    return r;
  }

  bool negative_ = false;
  Limbs limbs_;  // magnitude, least significant first, no leading zero limbs
};

// mantissa * 2^exponent, exactly.
struct Dyadic {
  BigInt mantissa;
  int exponent = 0;

  Dyadic() = default;  // zero
  explicit Dyadic(double v) {
    if (v == 0.0) return;
    int e = 0;
    const double f = std::frexp(v, &e);  // v = f * 2^e, 0.5 <= |f| < 1, exact
    mantissa = BigInt(static_cast<std::int64_t>(std::ldexp(f, 53)));
    exponent = e - 53;
  }
  Dyadic(BigInt m, int e) : mantissa(std::move(m)), exponent(e) {}

  int sign() const { return mantissa.sign(); }
  double approximate() const { return mantissa.approximate(exponent); }

  friend Dyadic operator+(const Dyadic& a, const Dyadic& b) {
    if (a.mantissa.is_zero()) return b;
    if (b.mantissa.is_zero()) return a;
    const int e = std::min(a.exponent, b.exponent);
    return Dyadic(a.mantissa.shifted_left(a.exponent - e) + b.mantissa.shifted_left(b.exponent - e),
                  e);
  }
  friend Dyadic operator-(const Dyadic& a, const Dyadic& b) {
    return a + Dyadic(-b.mantissa, b.exponent);
  }
  friend Dyadic operator*(const Dyadic& a, const Dyadic& b) {
    return Dyadic(a.mantissa * b.mantissa, a.exponent + b.exponent);
  }
};

inline int sign_of(double v) { return v > 0.0 ? 1 : (v < 0.0 ? -1 : 0); }

// Sum of doubles, exactly (used for expansions).
inline Dyadic exact_sum(const double* v, int n) {
  Dyadic total(0.0);
  for (int i = 0; i < n; ++i) total = total + Dyadic(v[i]);
  return total;
}

// (b - a) x (c - a): twice the signed area, positive counter-clockwise.
inline Dyadic orient_value(const deltri::Point& a, const deltri::Point& b, const deltri::Point& c) {
  const Dyadic ax(a.x), ay(a.y);
  const Dyadic ux = Dyadic(b.x) - ax, uy = Dyadic(b.y) - ay;
  const Dyadic vx = Dyadic(c.x) - ax, vy = Dyadic(c.y) - ay;
  return ux * vy - uy * vx;
}

inline int orient_sign(const deltri::Point& a, const deltri::Point& b, const deltri::Point& c) {
  return orient_value(a, b, c).sign();
}

// The 4x4 lifted determinant |x y x^2+y^2 1| of a, b, c, d, reduced with a as origin:
// it equals minus the 3x3 determinant of b - a, c - a, d - a with their lifts.
inline int incircle_sign(const deltri::Point& a, const deltri::Point& b, const deltri::Point& c,
                         const deltri::Point& d) {
  const Dyadic ax(a.x), ay(a.y);
  struct Row {
    Dyadic x, y, lift;
  };
  auto row = [&](const deltri::Point& p) {
    const Dyadic x = Dyadic(p.x) - ax, y = Dyadic(p.y) - ay;
    return Row{x, y, x * x + y * y};
  };
  const Row r1 = row(b), r2 = row(c), r3 = row(d);
  const Dyadic det = r1.x * (r2.y * r3.lift - r2.lift * r3.y) -
                     r1.y * (r2.x * r3.lift - r2.lift * r3.x) +
                     r1.lift * (r2.x * r3.y - r2.y * r3.x);
  return -det.sign();
}

// The 4x4 determinant by Leibniz's formula: the sum over all 24 permutations.
inline Dyadic determinant4(const Dyadic (&m)[4][4]) {
  int perm[4] = {0, 1, 2, 3};
  Dyadic total(0.0);
  do {
    int inversions = 0;
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) inversions += perm[i] > perm[j];
    const Dyadic term = m[0][perm[0]] * m[1][perm[1]] * m[2][perm[2]] * m[3][perm[3]];
    total = inversions % 2 ? total - term : total + term;
  } while (std::next_permutation(perm, perm + 4));
  return total;
}

// The sign deltri's incircle_perturbed must give: that of the 4x4 determinant of the rows
// (x, y, x^2 + y^2 - eps^rank, 1) of a, b, c, d (positive when d is inside the circle of a
// counter-clockwise a, b, c) for an infinitesimal eps > 0, rank 1, 2, ... in lexicographic (x, y)
// order of the four points. The determinant is affine in the lifts, so it is D0 minus, for each
// point, eps^rank times the determinant with the lift column replaced by that point's unit vector;
// the sign is that of the lowest power of eps with a nonzero coefficient. Points must be distinct.
inline int perturbed_incircle_sign(const deltri::Point& a, const deltri::Point& b, const deltri::Point& c,
                                   const deltri::Point& d) {
  const deltri::Point pts[4] = {a, b, c, d};
  Dyadic m[4][4];
  for (int i = 0; i < 4; ++i) {
    const Dyadic x(pts[i].x), y(pts[i].y);
    m[i][0] = x;
    m[i][1] = y;
    m[i][2] = x * x + y * y;
    m[i][3] = Dyadic(1.0);
  }
  const int unperturbed = determinant4(m).sign();
  if (unperturbed != 0) return unperturbed;
  std::vector<std::pair<std::pair<double, double>, int>> order;
  for (int i = 0; i < 4; ++i) order.push_back({{pts[i].x, pts[i].y}, i});
  std::sort(order.begin(), order.end());
  for (const auto& entry : order) {
    Dyadic unit[4][4];
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) unit[i][j] = j != 2 ? m[i][j] : Dyadic(i == entry.second ? 1.0 : 0.0);
    const int coefficient = -determinant4(unit).sign();
    if (coefficient != 0) return coefficient;
  }
  return 0;
}

// (a - p) . (b - p).
inline int dot_sign(const deltri::Point& a, const deltri::Point& b, const deltri::Point& p) {
  const Dyadic px(p.x), py(p.y);
  return ((Dyadic(a.x) - px) * (Dyadic(b.x) - px) + (Dyadic(a.y) - py) * (Dyadic(b.y) - py)).sign();
}

}  // namespace reference
