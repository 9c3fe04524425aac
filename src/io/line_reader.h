// Tokenised access to Triangle's text formats. The text is held in memory; a LineReader walks it
// one data line at a time and parses fields in place, so the hot path allocates nothing.
//
// Rules: '#' starts a comment anywhere; lines that are blank after removing the comment are
// skipped; fields are separated by whitespace or commas. Integers are decimal only (Triangle's
// octal/hex readings of "010"/"0x3" surprise users); reals are decimal with optional exponent and
// must be finite. A leading '+' is accepted on both. Anything else in a field is an error. A UTF-8
// byte order mark at the very start is skipped.
#pragma once

#include <cstddef>
#include <memory>
#include <string>

#include "io/file_text.h"

namespace deltri {

// Names a field for error messages; only turned into text when something is wrong.
// Renders as "<record> <number>: <field> [<ordinal>]", e.g. "vertex 7: y coordinate".
struct FieldName {
  const char* record;      // "vertex", "segment", "node header", ...
  long long number = -1;   // record number as the file counts it; < 0: none
  const char* field = "";  // "x coordinate", "attribute", ...
  int ordinal = 0;         // > 0: appended to field ("attribute 2")
};

class LineReader {
 public:
  // `name` is used in messages; `text` is the whole file.
  LineReader(std::string name, const std::string& text);
  LineReader(std::string name, FileText text);
  // Reads the file (standard input for "-"); throws InputError when it cannot. `threads` (at
  // least 1) bounds the threads that reading and parsing this text may take.
  static LineReader open(const std::string& path, int threads = kReadThreads);

  const std::string& name() const { return name_; }
  int threads() const { return threads_; }
  // Moves to the next line that has a field; false at end of text.
  bool next_line();
  // The 1-based number of the current line (after the end: the number of lines in the text).
  long line() const { return line_; }
  // Whether the current line has another field.
  bool has_field();

  long long read_int(const FieldName& name, long long lo, long long hi);
  double read_double(const FieldName& name);

  // Throws InputError(name, line(), message).
  [[noreturn]] void fail(const std::string& message) const;
  [[noreturn]] void fail(const FieldName& name, const std::string& problem) const;
  // How many bytes of text are still ahead; used only to bound memory reservations.
  std::size_t bytes_left() const { return static_cast<std::size_t>(end_ - pos_); }

  // --- for splitting a long list between threads ---
  // A place in the text, to come back to.
  struct Mark {
    const char* pos;
    long line;
    bool in_line;
  };
  Mark mark() const { return {pos_, line_, in_line_}; }
  void reset(const Mark& m) { pos_ = m.pos, line_ = m.line, in_line_ = m.in_line; }
  // A reader of the text from the first line that starts at least `bytes` ahead of this one's
  // position; its line numbers count from there (the first line it reads is line 1).
  LineReader tail_after(std::size_t bytes) const;
  // Makes this reader end where `tail` starts.
  void end_at(const LineReader& tail) { end_ = tail.pos_; }

 private:
  void skip_separators();
  void skip_past_newline();
  bool at_field_end(const char* p) const;
  std::string current_token() const;

  std::string name_;
  std::shared_ptr<const FileText> text_;  // shared: copies and moves keep the pointers valid
  const char* pos_;
  const char* end_;
  long line_ = 0;
  bool in_line_ = false;
  int threads_ = kReadThreads;
};

}  // namespace deltri
