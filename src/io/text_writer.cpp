#include "io/text_writer.h"

#include <algorithm>
#include <charconv>

namespace deltri {

void TextWriter::integer(long long value) {
  make_room(kLongestField);
  cur_ = std::to_chars(cur_, limit(), value).ptr;
}

void TextWriter::real(double value) {
  make_room(kLongestField);
  cur_ = std::to_chars(cur_, limit(), value).ptr;
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

}  // namespace deltri
