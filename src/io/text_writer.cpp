#include "io/text_writer.h"

#include <algorithm>
#include <bit>
#include <charconv>
#include <cstdint>
#include <cstring>

#include "io/digit_pairs.h"
#include "io/shortest_fixed.h"

namespace deltri {
namespace {


int digit_count(std::uint64_t v) {
  int n = 1;
  for (; v >= 10000; v /= 10000) n += 4;
  return n + (v >= 10) + (v >= 100) + (v >= 1000);
}

// Fills the digits from the back; only for numbers beyond 32 bits, which meshes never number.
char* format_unsigned(char* p, std::uint64_t v) {
  char* const end = p + digit_count(v);
  char* q = end;
  while (v >= 100) {
    q -= 2;
    std::memcpy(q, kDigitPairs.text + 2 * (v % 100), 2);
    v /= 100;
  }
  if (v >= 10) std::memcpy(q - 2, kDigitPairs.text + 2 * v, 2);
  else q[-1] = static_cast<char>('0' + v);
  return end;
}

void put_pair(char* p, std::uint32_t v) { std::memcpy(p, kDigitPairs.text + 2 * v, 2); }
void put_4(char* p, std::uint32_t v) {
  put_pair(p, v / 100);
  put_pair(p + 2, v % 100);
}
char* put_up_to_4(char* p, std::uint32_t v) {
  if (v < 10) {
    *p = static_cast<char>('0' + v);
    return p + 1;
  }
  if (v < 100) {
    put_pair(p, v);
    return p + 2;
  }
  if (v < 1000) {
    *p = static_cast<char>('0' + v / 100);
    put_pair(p + 1, v % 100);
    return p + 3;
  }
  put_4(p, v);
  return p + 4;
}

// Mesh numbers: split into groups of four digits first, so that the pairs within a group do not
// wait for each other's divisions as they do when one number is divided by 100 again and again.
char* format_unsigned(char* p, std::uint32_t v) {
  if (v < 10000) return put_up_to_4(p, v);
  if (v < 100000000) {
    p = put_up_to_4(p, v / 10000);
    put_4(p, v % 10000);
    return p + 4;
  }
  p = put_up_to_4(p, v / 100000000);
  const std::uint32_t rest = v % 100000000;
  put_4(p, rest / 10000);
  put_4(p + 4, rest % 10000);
  return p + 8;
}

}  // namespace

char* format_integer(char* p, long long value) {
  // The magnitude as unsigned: also right for LLONG_MIN, whose negation overflows.
  std::uint64_t magnitude = static_cast<std::uint64_t>(value);
  if (value < 0) {
    *p++ = '-';
    magnitude = 0 - magnitude;
  }
  if (magnitude <= UINT32_MAX) return format_unsigned(p, static_cast<std::uint32_t>(magnitude));
  return format_unsigned(p, magnitude);
}

char* TextWriter::format_declined_real(char* p, double value) {
  static_assert(kShortestFixedScratch <= kLongestField - 1);  // format_real: room is made for a separator too
  const auto bits = std::bit_cast<std::uint64_t>(value);  // -0.0 and 0.0 print differently
  if (bits == 0) {  // 0.0, the other value a strip's vertices alternate with
    *p = '0';
    return p + 1;
  }
  if (bits != slow_bits_) {
    slow_length_ = static_cast<std::uint32_t>(std::to_chars(slow_text_, slow_text_ + kLongestField, value).ptr - slow_text_);
    slow_bits_ = bits;
  }
  static_assert(kLongestDouble <= kLongestField - 1);  // room is made for a separator too
  std::memcpy(p, slow_text_, kLongestDouble);
  return p + slow_length_;
}

void TextWriter::text(std::string_view s) {
  while (!s.empty()) {
    make_room(1);
    const std::size_t n = std::min(s.size(), static_cast<std::size_t>(limit() - cur_));
    s.copy(cur_, n);
    cur_ += n;
    s.remove_prefix(n);
  }
}

void TextWriter::flush() {
  if (cur_ != buffer_) sink_.write(buffer_, static_cast<std::size_t>(cur_ - buffer_));
  cur_ = buffer_;
}

void TextWriter::finish() { flush(); }

void TextWriter::write_lines(std::size_t items, std::function<void(TextWriter&, std::size_t, std::size_t)> format) {
  flush();
  sink_.write_ranges({items, kItemsPerRange, std::move(format)});
}

void ByteSink::write_ranges(const LineRanges& ranges) {
  TextWriter out(*this);
  for (std::size_t r = 0; r < ranges.count(); ++r) ranges.format(out, ranges.begin(r), ranges.end(r));
  out.finish();
}

}  // namespace deltri
