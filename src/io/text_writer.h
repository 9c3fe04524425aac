// Fast text output for the writers. Fields are formatted (integers from a digit-pair table, reals
// with std::to_chars) into a fixed chunk that is handed to a ByteSink when full, so a writer
// never builds per-line strings and can stream a file of any size. Reals use the shortest form
// that reads back to the identical double (Triangle uses %.17g: same values, sometimes longer
// text).
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>

#include "io/shortest_fixed.h"

namespace deltri {

class TextWriter;

// The body of a file as ranges of items (vertices, triangle slots), each range formatted on its
// own: then free threads can format different ranges of one large file at once. `format` writes
// the lines of items [begin, end) and must not modify shared state.
struct LineRanges {
  std::size_t items = 0;
  std::size_t per_range = 1;
  std::function<void(TextWriter&, std::size_t begin, std::size_t end)> format;
  std::size_t count() const { return (items + per_range - 1) / per_range; }
  std::size_t begin(std::size_t r) const { return r * per_range; }
  std::size_t end(std::size_t r) const { return r + 1 < count() ? (r + 1) * per_range : items; }
};

// Where formatted bytes go: a string in memory, or a file being written.
class ByteSink {
 public:
  virtual ~ByteSink() = default;
  virtual void write(const char* data, std::size_t size) = 0;
  // A hint that about `bytes` more are coming; lets a string grow once instead of repeatedly.
  virtual void expect(std::size_t /*bytes*/) {}
  // Writes the ranges' lines in order. Here one after another on the calling thread; a file
  // being written by an OutputSet lets idle threads format ranges too (same bytes either way).
  virtual void write_ranges(const LineRanges& ranges);
};

class StringSink final : public ByteSink {
 public:
  explicit StringSink(std::string& out) : out_(out) {}
  void write(const char* data, std::size_t size) override { out_.append(data, size); }
  void expect(std::size_t bytes) override { out_.reserve(out_.size() + bytes); }

 private:
  std::string& out_;
};

// Writes decimal `value` at p and returns the end. Digits are produced two at a time from a
// table, and at most 20 digits and a sign are written.
char* format_integer(char* p, long long value);

// Fields on a line are separated by one space: Triangle's column padding carries no meaning and
// every reader (Triangle's included) accepts any run of whitespace.
class TextWriter {
  static constexpr std::size_t kChunk = 1 << 16;
  static constexpr std::size_t kLongestField = 32;  // a separator and a double (at most 24 characters)
  static constexpr std::size_t kLongestDouble = 24;

 public:
  explicit TextWriter(ByteSink& sink) : sink_(sink) {}
  TextWriter(const TextWriter&) = delete;
  TextWriter& operator=(const TextWriter&) = delete;
  // Not flushed here: a destructor must not throw, and a half-written file is no use anyway.
  ~TextWriter() = default;

  void integer(long long value) {
    make_room(kLongestField);
    cur_ = format_integer(cur_, value);
  }
  void real(double value) {
    make_room(kLongestField);
    cur_ = format_real(cur_, value);
  }
  // A following field: a space, then the value.
  void next_integer(long long value) {
    make_room(kLongestField);
    *cur_++ = ' ';
    cur_ = format_integer(cur_, value);
  }
  void next_real(double value) {
    make_room(kLongestField);
    *cur_++ = ' ';
    cur_ = format_real(cur_, value);
  }
  void text(std::string_view s);
  void end_line() {
    make_room(1);
    *cur_++ = '\n';
  }
  // Hands everything still buffered to the sink; call once at the end (or before write_lines).
  void finish();

  // Items per range of write_lines: large enough that handing a range between threads costs
  // little next to formatting it (about 100 KB of text), small enough that the ranges in flight
  // do not raise the peak memory.
  static constexpr std::size_t kItemsPerRange = 2048;
  // Writes the lines of `items` items, kItemsPerRange at a time, through the sink's
  // write_ranges: what is buffered is handed on first, so the bytes come out in order.
  void write_lines(std::size_t items, std::function<void(TextWriter&, std::size_t begin, std::size_t end)> format);

  // The fast way to write the millions of lines of a mesh: one check for buffer space per line
  // instead of one per field. `out.line(n)` makes room for up to n fields and the newline (n at
  // most kMaxLineFields); the Line has the same field calls as the writer, and end_line() hands
  // the line back. The position is kept in the Line, in a local, because every character stored
  // through a char pointer could otherwise alias the writer's own position and force reloads.
  static constexpr std::size_t kMaxLineFields = 256;
  class Line {
   public:
    void integer(long long value) { cur_ = format_integer(cur_, value); }
    void real(double value) { cur_ = writer_.format_real(cur_, value); }
    void next_integer(long long value) {
      *cur_++ = ' ';
      cur_ = format_integer(cur_, value);
    }
    void next_real(double value) {
      *cur_++ = ' ';
      cur_ = writer_.format_real(cur_, value);
    }
    void end_line() {
      *cur_++ = '\n';
      writer_.cur_ = cur_;
    }

   private:
    friend class TextWriter;
    explicit Line(TextWriter& writer) : writer_(writer), cur_(writer.cur_) {}
    TextWriter& writer_;
    char* cur_;
  };
  Line line(std::size_t fields) {
    make_room(fields * kLongestField + 1);
    return Line(*this);
  }

 private:
  static_assert(kMaxLineFields * kLongestField + 1 <= kChunk);

  // Shortest text that reads back as the identical double.
  char* format_real(char* p, double value) {
    if (char* end = format_shortest_fixed(p, value)) return end;
    return format_declined_real(p, value);
  }
  // What format_shortest_fixed declines: std::to_chars's text.
  char* format_declined_real(char* p, double value);
  // The last value other than 0 that format_shortest_fixed left to std::to_chars, and its text: a
  // mesh repeats such values line after line (a strip's vertices alternate between its sides, y = 0
  // and y = 1e-05), and a copy is a tenth of the conversion.
  std::uint64_t slow_bits_ = 0;  // 0 (the bits of 0.0, never kept): nothing kept
  std::uint32_t slow_length_ = 0;
  char slow_text_[kLongestField] = {};
  void make_room(std::size_t bytes) {
    if (static_cast<std::size_t>(limit() - cur_) < bytes) flush();
  }
  char* limit() { return buffer_ + kChunk; }
  void flush();

  ByteSink& sink_;
  char buffer_[kChunk];
  char* cur_ = buffer_;
};

}  // namespace deltri
