#include "io/line_reader.h"

#include <charconv>
#include <cmath>
#include <cstring>
#include <algorithm>

#include "io/decimal_parse.h"
#include "io/file_text.h"
#include "util/errors.h"

namespace deltri {
namespace {

bool is_separator(char c) { return c == ' ' || c == ',' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

// Garbage (binary files, other formats) is quoted in messages; keep it short and printable.
std::string printable(const char* begin, const char* end) {
  constexpr std::size_t kMaxShown = 40;
  std::string out;
  for (const char* p = begin; p < end && out.size() < kMaxShown; ++p) {
    const auto c = static_cast<unsigned char>(*p);
    if (c >= 0x20 && c < 0x7f) {
      out += static_cast<char>(c);
    } else {
      static const char kHex[] = "0123456789abcdef";
      out += "\\x";
      out += kHex[c >> 4];
      out += kHex[c & 15];
    }
  }
  if (end - begin > static_cast<std::ptrdiff_t>(kMaxShown)) out += "...";
  return out;
}

std::string describe(const FieldName& name) {
  std::string s = name.record;
  if (name.number >= 0) s += " " + std::to_string(name.number);
  s += ": ";
  s += name.field;
  if (name.ordinal > 0) s += " " + std::to_string(name.ordinal);
  return s;
}

}  // namespace

LineReader::LineReader(std::string name, FileText text)
    : name_(std::move(name)), text_(std::make_shared<const FileText>(std::move(text))) {
  pos_ = text_->data();
  end_ = pos_ + text_->size;
  // Windows editors may start a UTF-8 file with a byte order mark; Triangle's scanner skips it
  // as it skips any non-numeric text, and a user cannot see it, so it is no error here either.
  if (end_ - pos_ >= 3 && std::memcmp(pos_, "\xEF\xBB\xBF", 3) == 0) pos_ += 3;
}

namespace {
FileText copy_text(const std::string& text) {
  FileText copy{BigBytes(text.size() + 1), text.size()};
  text.copy(copy.bytes.get(), text.size());
  return copy;
}
}  // namespace

LineReader::LineReader(std::string name, const std::string& text) : LineReader(std::move(name), copy_text(text)) {}

LineReader LineReader::tail_after(std::size_t bytes) const {
  LineReader tail = *this;
  tail.pos_ = pos_ + std::min(bytes, bytes_left());
  if (tail.pos_ > pos_ && tail.pos_[-1] != '\n') tail.skip_past_newline();
  tail.line_ = 0;
  tail.in_line_ = false;
  return tail;
}

LineReader LineReader::open(const std::string& path, int threads) {
  LineReader in(path == "-" ? kStandardInputName : path, read_file_text(path, threads));
  in.threads_ = threads;
  return in;
}

void LineReader::skip_separators() {
  while (pos_ < end_ && is_separator(*pos_)) ++pos_;
}

void LineReader::skip_past_newline() {
  const void* nl = std::memchr(pos_, '\n', static_cast<std::size_t>(end_ - pos_));
  pos_ = nl ? static_cast<const char*>(nl) + 1 : end_;
}

bool LineReader::next_line() {
  if (in_line_) skip_past_newline();
  in_line_ = false;
  while (pos_ < end_) {
    ++line_;
    skip_separators();
    if (pos_ < end_ && *pos_ != '\n' && *pos_ != '#') {
      in_line_ = true;
      return true;
    }
    skip_past_newline();
  }
  return false;
}

bool LineReader::has_field() {
  if (!in_line_) return false;
  skip_separators();
  return pos_ < end_ && *pos_ != '\n' && *pos_ != '#';
}

bool LineReader::at_field_end(const char* p) const {
  return p == end_ || *p == '\n' || *p == '#' || is_separator(*p);
}

std::string LineReader::current_token() const {
  const char* e = pos_;
  while (!at_field_end(e)) ++e;
  return printable(pos_, e);
}

long long LineReader::read_int(const FieldName& name, long long lo, long long hi) {
  if (!has_field()) fail(name, "is missing");
  const char* p = pos_;
  if (*p == '+' && p + 1 < end_ && *(p + 1) != '-') ++p;
  long long value = 0;
  const char* fast_end = nullptr;
  if (decimal::parse_int(p, end_, value, &fast_end) && at_field_end(fast_end) && value >= lo && value <= hi) {
    pos_ = fast_end;
    return value;
  }
  // Everything else, errors included, as std::from_chars sees it.
  const auto [ptr, ec] = std::from_chars(p, end_, value);
  if (ec == std::errc::result_out_of_range && at_field_end(ptr)) fail(name, "is too large: '" + current_token() + "'");
  if (ec != std::errc() || !at_field_end(ptr)) fail(name, "is not an integer: '" + current_token() + "'");
  if (value < lo || value > hi)
    fail(name, "must be between " + std::to_string(lo) + " and " + std::to_string(hi) + ", not " +
                   std::to_string(value));
  pos_ = ptr;
  return value;
}

double LineReader::read_double(const FieldName& name) {
  if (!has_field()) fail(name, "is missing");
  const char* p = pos_;
  if (*p == '+' && p + 1 < end_ && *(p + 1) != '-') ++p;
  double value = 0.0;
  const char* fast_end = nullptr;
  if (decimal::parse_double(p, end_, value, &fast_end) && at_field_end(fast_end)) {  // always finite
    pos_ = fast_end;
    return value;
  }
  // Everything else, errors included, as std::from_chars sees it.
  const auto [ptr, ec] = std::from_chars(p, end_, value, std::chars_format::general);
  if (ec == std::errc::result_out_of_range && at_field_end(ptr))
    fail(name, "is out of the range of doubles: '" + current_token() + "'");
  if (ec != std::errc() || !at_field_end(ptr)) fail(name, "is not a number: '" + current_token() + "'");
  if (!std::isfinite(value)) fail(name, "is not a finite number: '" + current_token() + "'");
  pos_ = ptr;
  return value;
}

void LineReader::fail(const std::string& message) const { throw InputError(name_, line_, message); }

void LineReader::fail(const FieldName& name, const std::string& problem) const {
  fail(describe(name) + " " + problem);
}

}  // namespace deltri
