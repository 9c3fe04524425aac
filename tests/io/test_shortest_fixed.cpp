// The fast path for writing doubles must give exactly std::to_chars's characters wherever it
// accepts a value, and must accept the magnitudes mesh coordinates usually have.
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "harness/check.h"
#include "io/shortest_fixed.h"
#include "io/text_writer.h"

using namespace deltri;

namespace {

struct Comparison {
  long accepted = 0, disagreements = 0;
  std::string first_bad;

  void check(double v) {
    char fast[64], slow[64];
    std::memset(fast, '#', sizeof fast);  // scratch bytes past the end must not matter
    const char* end = format_shortest_fixed(fast, v);
    if (!end) return;
    ++accepted;
    const std::string a(static_cast<const char*>(fast), end);
    const std::string b(slow, std::to_chars(slow, slow + sizeof slow, v).ptr);
    if (a != b && disagreements++ == 0) first_bad = b + " written as " + a;
  }
  // v and its k nearest neighbours on each side.
  void check_around(double v, int k) {
    double up = v, down = v;
    check(v);
    for (int i = 0; i < k; ++i) {
      up = std::nextafter(up, INFINITY);
      down = std::nextafter(down, -INFINITY);
      check(up);
      check(down);
    }
  }
};

}  // namespace

TEST(shortest_fixed_matches_to_chars_on_random_bits) {
  std::mt19937_64 rng(11);
  Comparison c;
  for (int i = 0; i < 300000; ++i) {
    const std::uint64_t exponent = 1016 + rng() % 17;  // 2^-7 .. 2^9, a little beyond the range
    const double v = std::bit_cast<double>((exponent << 52) | (rng() & ((std::uint64_t{1} << 52) - 1)));
    c.check(v);
    c.check(-v);
  }
  CHECK_EQ(c.disagreements, 0);
  if (c.disagreements) std::printf("  first: %s\n", c.first_bad.c_str());
  CHECK(c.accepted > 400000);
}

TEST(shortest_fixed_matches_to_chars_on_short_decimals_and_boundaries) {
  Comparison c;
  for (int digits = 0; digits <= 6; ++digits) {
    const double scale = std::pow(10.0, digits);
    for (int k = 1; k < 20000; ++k) c.check_around(k / scale, 2);
  }
  for (int e = -8; e <= 10; ++e) c.check_around(std::ldexp(1.0, e), 4);  // gap below is halved
  for (double v : {0.01, 0.1, 1.0, 10.0, 100.0, 1000.0, 999.9999999999999, 0.3, 0.7, 123.456})
    c.check_around(v, 4);
  for (int k = 0; k < 1000; ++k) c.check_around(k + 0.5, 1);
  CHECK_EQ(c.disagreements, 0);
  if (c.disagreements) std::printf("  first: %s\n", c.first_bad.c_str());
}

TEST(shortest_fixed_declines_outside_its_range) {
  char buf[64];
  const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
  for (double v : {0.0, -0.0, 0.00999, 1000.0, -1000.0, 1e300, 5e-324, inf, -inf, nan})
    CHECK(format_shortest_fixed(buf, v) == nullptr);
}

TEST(text_writer_reals_match_to_chars) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::string text, expected;
  StringSink sink(text);
  TextWriter out(sink);
  for (int i = 0; i < 100000; ++i) {
    const double v = i % 3 == 0 ? unit(rng) : i % 3 == 1 ? -1000 * unit(rng) : std::ldexp(unit(rng), static_cast<int>(rng() % 40) - 20);
    out.next_real(v);
    char buf[64];
    expected += ' ';
    expected.append(buf, std::to_chars(buf, buf + sizeof buf, v).ptr);
  }
  out.finish();
  CHECK(text == expected);
}

// The writer keeps the text of the last value the fast path declined (and writes 0.0 itself): a
// repeat, a value of the same magnitude, -0.0 beside 0.0, NaN and the infinities must still come
// out as std::to_chars writes each of them alone, through fields and through lines.
TEST(text_writer_repeated_slow_reals_match_to_chars) {
  const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
  const double values[] = {1e-05, 0.0, 1e-05, 1e-05, -0.0, 0.0, -1e-05, 1.0000000000000002e-05, 0.0, nan, nan,
                           inf,   -inf, 5e-324, 5e-324, 1e300, 0.5,   1e300,  2e-05, 0.0, -0.0, -0.0, 1e-05};
  std::string text, expected;
  StringSink sink(text);
  TextWriter out(sink);
  for (int pass = 0; pass < 2; ++pass) {
    for (double v : values) {
      if (pass == 0) out.next_real(v);
      else {
        TextWriter::Line line = out.line(1);
        line.next_real(v);
        line.end_line();
      }
      char buf[64];
      expected += ' ';
      expected.append(buf, std::to_chars(buf, buf + sizeof buf, v).ptr);
      if (pass == 1) expected += '\n';
    }
  }
  out.finish();
  CHECK(text == expected);
}
