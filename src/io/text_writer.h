// Fast text output for the writers. Fields are formatted with std::to_chars into a fixed chunk
// that is handed to a ByteSink when full, so a writer never builds per-line strings and can
// stream a file of any size. Reals use the shortest form that reads back to the identical
// double (Triangle uses %.17g: same values, sometimes longer text).
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace deltri {

// Where formatted bytes go: a string in memory, or a file being written.
class ByteSink {
 public:
  virtual ~ByteSink() = default;
  virtual void write(const char* data, std::size_t size) = 0;
  // A hint that about `bytes` more are coming; lets a string grow once instead of repeatedly.
  virtual void expect(std::size_t /*bytes*/) {}
};

class StringSink final : public ByteSink {
 public:
  explicit StringSink(std::string& out) : out_(out) {}
  void write(const char* data, std::size_t size) override { out_.append(data, size); }
  void expect(std::size_t bytes) override { out_.reserve(out_.size() + bytes); }

 private:
  std::string& out_;
};

// Fields on a line are separated by one space: Triangle's column padding carries no meaning and
// every reader (Triangle's included) accepts any run of whitespace.
class TextWriter {
 public:
  explicit TextWriter(ByteSink& sink) : sink_(sink) {}
  TextWriter(const TextWriter&) = delete;
  TextWriter& operator=(const TextWriter&) = delete;
  // Not flushed here: a destructor must not throw, and a half-written file is no use anyway.
  ~TextWriter() = default;

  void integer(long long value);
  void real(double value);
  // A following field: a space, then the value.
  void next_integer(long long value) { put(' '); integer(value); }
  void next_real(double value) { put(' '); real(value); }
  void text(std::string_view s);
  void end_line() { put('\n'); }
  // Hands everything still buffered to the sink; call once at the end.
  void finish();

 private:
  static constexpr std::size_t kChunk = 1 << 16;
  static constexpr std::size_t kLongestField = 32;  // a double needs at most 24 characters

  void make_room(std::size_t bytes) {
    if (static_cast<std::size_t>(limit() - cur_) < bytes) flush();
  }
  void put(char c) {
    make_room(1);
    *cur_++ = c;
  }
  char* limit() { return buffer_ + kChunk; }
  void flush();

  ByteSink& sink_;
  char buffer_[kChunk];
  char* cur_ = buffer_;
};

}  // namespace deltri
