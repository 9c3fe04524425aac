// The fast number paths must agree bit for bit with std::from_chars / std::to_chars.
#include <charconv>
#include <climits>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "harness/check.h"
#include "io/decimal_parse.h"
#include "io/line_reader.h"
#include "io/text_writer.h"

using namespace deltri;

namespace {

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

std::string shortest(double v) {
  char buf[64];
  return std::string(buf, std::to_chars(buf, buf + sizeof buf, v).ptr);
}

std::string with_format(double v, std::chars_format format, int precision) {
  char buf[512];
  return std::string(buf, std::to_chars(buf, buf + sizeof buf, v, format, precision).ptr);
}

// Compares the fast path with from_chars on `s`; counts accepted inputs. When the fast path
// accepts, it must stop where from_chars stops and give the same bits.
struct Agreement {
  long tried = 0, accepted = 0, disagreements = 0;
  std::string first_bad;

  void check(const std::string& s) {
    ++tried;
    const char* first = s.data();
    const char* last = s.data() + s.size();
    double fast = 0.0;
    const char* fast_end = nullptr;
    if (!decimal::parse_double(first, last, fast, &fast_end)) return;
    ++accepted;
    double slow = 0.0;
    const auto [slow_end, ec] = std::from_chars(first, last, slow, std::chars_format::general);
    if (ec != std::errc() || slow_end != fast_end || !same_bits(fast, slow)) {
      if (disagreements++ == 0) first_bad = s;
    }
  }
};

std::string random_digits(std::mt19937_64& rng, int count) {
  std::string s;
  for (int i = 0; i < count; ++i) s += static_cast<char>('0' + rng() % 10);
  return s;
}

}  // namespace

TEST(decimal_shortest_output_of_random_doubles) {
  std::mt19937_64 rng(20240601);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  Agreement typical, scaled;
  for (int i = 0; i < 200000; ++i) {
    const double u = unit(rng);
    typical.check(shortest(u));
    typical.check(shortest(-u * 1000.0));
    scaled.check(shortest(std::ldexp(u, static_cast<int>(rng() % 140) - 70)));
  }
  CHECK_EQ(typical.disagreements + scaled.disagreements, 0);
  CHECK_EQ(typical.first_bad + scaled.first_bad, "");
  // The point of the fast path: nearly every coordinate of a typical file takes it.
  CHECK(typical.accepted > typical.tried * 99 / 100);
}

TEST(decimal_random_bit_patterns_in_every_format) {
  std::mt19937_64 rng(99);
  Agreement a;
  for (int i = 0; i < 100000; ++i) {
    std::uint64_t bits = rng();
    double v;
    std::memcpy(&v, &bits, sizeof v);
    if (!std::isfinite(v)) continue;
    a.check(shortest(v));
    a.check(with_format(v, std::chars_format::scientific, static_cast<int>(rng() % 25)));
    a.check(with_format(v, std::chars_format::general, static_cast<int>(1 + rng() % 25)));
    if (std::fabs(v) < 1e30 && std::fabs(v) > 1e-30)
      a.check(with_format(v, std::chars_format::fixed, static_cast<int>(rng() % 30)));
  }
  CHECK_EQ(a.disagreements, 0);
  CHECK_EQ(a.first_bad, "");
}

TEST(decimal_random_digit_strings) {
  // Long mantissas, leading zeros, points anywhere, exponents of every size, signs.
  std::mt19937_64 rng(4242);
  Agreement a;
  for (int i = 0; i < 300000; ++i) {
    std::string s;
    if (rng() % 3 == 0) s += '-';
    s += std::string(rng() % 4 == 0 ? rng() % 12 : 0, '0');
    std::string digits = random_digits(rng, 1 + static_cast<int>(rng() % 24));
    if (rng() % 2) digits.insert(rng() % (digits.size() + 1), ".");
    s += digits;
    switch (rng() % 4) {
      case 0: break;
      case 1: s += "e" + std::to_string(static_cast<int>(rng() % 61) - 30); break;
      case 2: s += (rng() % 2 ? "E+" : "e-") + std::to_string(rng() % 400); break;
      default: s += "e" + std::string(rng() % 3, '0') + std::to_string(rng() % 25); break;
    }
    a.check(s);
  }
  CHECK_EQ(a.disagreements, 0);
  CHECK_EQ(a.first_bad, "");
  CHECK(a.accepted > a.tried / 3);
}

TEST(decimal_halfway_and_boundary_cases) {
  // Exact midpoints between two doubles must not be rounded twice: integers between 2^53 and
  // 10^19 are exact decimals, and every odd one above 2^53 lies halfway between doubles there.
  std::mt19937_64 rng(7);
  Agreement a;
  std::vector<std::uint64_t> values{(1ull << 53) - 1, 1ull << 53, (1ull << 53) + 1, (1ull << 53) + 3,
                                    (1ull << 54) + 2, (1ull << 63) - 1, 1ull << 63, (1ull << 63) + 1024,
                                    (1ull << 63) + 1025, 9999999999999999999ull, 10000000000000000ull};
  for (int i = 0; i < 100000; ++i) {
    const int bits = 54 + static_cast<int>(rng() % 10);
    const std::uint64_t base = (std::uint64_t{1} << (bits - 1)) | (rng() >> (65 - bits));
    // Clear the low bits below the double's precision and put the midpoint pattern there.
    const int dropped = bits - 53;
    values.push_back((base >> dropped << dropped) | (std::uint64_t{1} << (dropped - 1)));
    values.push_back(base);
  }
  for (const std::uint64_t v : values) {
    const std::string digits = std::to_string(v);
    a.check(digits);
    // The same digits with the point moved and the exponent compensating, or not.
    for (int shift : {1, 5, 17}) {
      if (shift >= static_cast<int>(digits.size())) continue;
      const std::string moved = digits.substr(0, digits.size() - shift) + "." + digits.substr(digits.size() - shift);
      a.check(moved);
      a.check(moved + "e" + std::to_string(shift));
      a.check("0." + digits + "e" + std::to_string(digits.size()));
      a.check(digits + "e-" + std::to_string(shift + 8));
    }
  }
  // Near the ends of the exact power tables and of the double range.
  for (const char* s : {"1e22", "1e23", "9007199254740993e22", "9007199254740993e-22", "123456789012345678e27",
                        "1e-27", "1.7976931348623157e308", "2.2250738585072014e-308", "2.2250738585072011e-308",
                        "4.9406564584124654e-324", "5e-324", "1e-400", "0.0000000000000000000000000001",
                        "00000000000000000000000000000001.5", "1.00000000000000000000000001", "9999999999999999999",
                        "99999999999999999999", "18446744073709551615", "18446744073709551616", "0e999", "-0",
                        "-0.0e-5", "0.", ".5", "5.", "1.e3", "-.25", "7e0", "7e-0", "7e+0", "1e0001", "1e00001"})
    a.check(s);
  CHECK_EQ(a.disagreements, 0);
  CHECK_EQ(a.first_bad, "");
}

TEST(decimal_negative_zero_and_stop_positions) {
  double v = 1.0;
  const char* end = nullptr;
  const std::string neg_zero = "-0.000";
  REQUIRE(decimal::parse_double(neg_zero.data(), neg_zero.data() + neg_zero.size(), v, &end));
  CHECK(v == 0.0 && std::signbit(v));
  // from_chars stops before an exponent without digits and at anything that is not a digit;
  // the fast path either stops at the same place or declines.
  Agreement a;
  for (const char* s : {"1e", "1e+", "1e-", "1.5x", "12345678x", "1234567x9", "0x10", "1,5", "2.5 3", "1e5e5",
                        "--1", "-", ".", "", "e5", "-.e5", "1.2.3", "123456781234567:", "12345678/2345678"})
    a.check(s);
  CHECK_EQ(a.disagreements, 0);
  CHECK_EQ(a.first_bad, "");
}

TEST(decimal_eight_digit_blocks_reject_every_non_digit) {
  // Each byte value in each position of an eight-byte block, followed by more digits.
  Agreement a;
  for (int position = 0; position < 8; ++position) {
    for (int byte = 1; byte < 256; ++byte) {
      std::string s = "0.1234567812345678";
      s[2 + position] = static_cast<char>(byte);
      a.check(s);
      s = "1234567812345678";
      s[8 + position] = static_cast<char>(byte);
      a.check(s);
    }
  }
  CHECK_EQ(a.disagreements, 0);
  CHECK_EQ(a.first_bad, "");
}

TEST(decimal_integers_agree_with_from_chars) {
  std::mt19937_64 rng(5);
  std::vector<std::string> inputs{"0", "-0", "000000000000000000000000007", "-000123", "999999999999999999",
                                  "1000000000000000000", "9223372036854775807", "-9223372036854775808",
                                  "9223372036854775808", "-", "", "12a", "1.5", "+1", "1e3"};
  for (int i = 0; i < 100000; ++i) {
    std::string s = rng() % 4 == 0 ? "-" : "";
    s += random_digits(rng, 1 + static_cast<int>(rng() % 21));
    inputs.push_back(s);
  }
  long disagreements = 0, accepted = 0;
  for (const std::string& s : inputs) {
    long long fast = 0;
    const char* fast_end = nullptr;
    if (!decimal::parse_int(s.data(), s.data() + s.size(), fast, &fast_end)) continue;
    ++accepted;
    long long slow = 0;
    const auto [slow_end, ec] = std::from_chars(s.data(), s.data() + s.size(), slow);
    disagreements += ec != std::errc() || slow_end != fast_end || slow != fast;
  }
  CHECK_EQ(disagreements, 0);
  CHECK(accepted > 50000);
}

TEST(decimal_line_reader_matches_from_chars_with_and_without_fast_path) {
  // Through the reader, fallbacks included: every value equals from_chars of the same text.
  std::mt19937_64 rng(11);
  std::string text;
  std::vector<double> expected;
  for (int i = 0; i < 20000; ++i) {
    std::uint64_t bits = rng();
    double v;
    std::memcpy(&v, &bits, sizeof v);
    if (!std::isfinite(v)) v = 0.5;
    const std::string s = i % 3 == 0 ? with_format(v, std::chars_format::scientific, 20) : shortest(v);
    double slow = 0.0;
    std::from_chars(s.data(), s.data() + s.size(), slow);
    expected.push_back(slow);
    text += (i % 5 == 0 && s[0] != '-' ? "+" : "") + s + (i % 4 == 3 ? "\n" : i % 2 ? "," : " \t");
  }
  LineReader in("t", text);
  std::size_t k = 0;
  bool same = true;
  while (in.next_line()) {
    while (in.has_field()) {
      const double v = in.read_double({"r"});
      same = same && k < expected.size() && same_bits(v, expected[k]);
      ++k;
    }
  }
  CHECK(same);
  CHECK_EQ(k, expected.size());
}

TEST(text_writer_integers_match_to_chars) {
  std::mt19937_64 rng(3);
  std::vector<long long> values{0, -1, 1, 9, 10, 99, 100, LLONG_MAX, LLONG_MIN, LLONG_MIN + 1, 4294967295LL,
                                4294967296LL, -4294967295LL, -4294967296LL};
  for (long long p = 1; p <= LLONG_MAX / 10; p *= 10) {
    values.insert(values.end(), {p - 1, p, p + 1, -p, 1 - p});
  }
  for (int i = 0; i < 100000; ++i) {
    const long long v = static_cast<long long>(rng() >> (rng() % 64));
    values.push_back(i % 2 ? v : -v);
  }
  long disagreements = 0;
  for (const long long v : values) {
    char fast[32], slow[32];
    const std::string a(fast, format_integer(fast, v));
    const std::string b(slow, std::to_chars(slow, slow + sizeof slow, v).ptr);
    disagreements += a != b;
  }
  CHECK_EQ(disagreements, 0);
}

TEST(text_writer_lines_match_field_by_field_output) {
  // Many lines cross the chunk boundary; both ways of writing must give the same text.
  std::mt19937_64 rng(8);
  std::string by_line, by_field;
  StringSink line_sink(by_line), field_sink(by_field);
  TextWriter lines(line_sink), fields(field_sink);
  for (int i = 0; i < 50000; ++i) {
    std::uint64_t bits = rng();
    double v;
    std::memcpy(&v, &bits, sizeof v);
    if (!std::isfinite(v)) v = -0.0;
    const long long n = static_cast<long long>(rng()) >> (rng() % 64);
    const int extra = static_cast<int>(rng() % 4) * (i % 100 == 0 ? 60 : 1);  // sometimes long lines
    TextWriter::Line line = lines.line(3 + static_cast<std::size_t>(extra));
    line.integer(n);
    line.next_real(v);
    line.next_integer(-n);
    for (int e = 0; e < extra; ++e) line.next_real(v * e);
    line.end_line();
    fields.integer(n);
    fields.next_real(v);
    fields.next_integer(-n);
    for (int e = 0; e < extra; ++e) fields.next_real(v * e);
    fields.end_line();
  }
  lines.finish();
  fields.finish();
  CHECK(by_line.size() > (std::size_t{1} << 20));
  CHECK(by_line == by_field);
}
