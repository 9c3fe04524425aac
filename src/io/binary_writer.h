// Raw output for the binary variants of the single-file formats (MSH binary, VTU appended data):
// values are copied byte for byte in the machine's own order (both formats say which order that
// is: MSH by the integer 1 in its header, VTU by its byte_order attribute), through a fixed chunk
// handed to a ByteSink when full, like TextWriter.
#pragma once

#include <cstddef>
#include <cstring>
#include <string_view>
#include <type_traits>

#include "io/text_writer.h"

namespace deltri {

class BinaryWriter {
  static constexpr std::size_t kChunk = 1 << 16;

 public:
  explicit BinaryWriter(ByteSink& sink) : sink_(sink) {}
  BinaryWriter(const BinaryWriter&) = delete;
  BinaryWriter& operator=(const BinaryWriter&) = delete;

  template <class T>
  void put(T value) {
    static_assert(std::is_trivially_copyable_v<T>);
    if (used_ + sizeof value > kChunk) flush();
    std::memcpy(buffer_ + used_, &value, sizeof value);
    used_ += sizeof value;
  }
  // Text goes through as its bytes (the ASCII parts of a binary file).
  void text(std::string_view s) {
    while (!s.empty()) {
      if (used_ == kChunk) flush();
      const std::size_t n = std::min(s.size(), kChunk - used_);
      std::memcpy(buffer_ + used_, s.data(), n);
      used_ += n;
      s.remove_prefix(n);
    }
  }
  // Hands everything buffered to the sink; call at the end (and before writing to the sink
  // another way).
  void finish() { flush(); }

 private:
  void flush() {
    if (used_ > 0) sink_.write(buffer_, used_);
    used_ = 0;
  }
  ByteSink& sink_;
  char buffer_[kChunk];
  std::size_t used_ = 0;
};

}  // namespace deltri
