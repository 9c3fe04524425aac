// Every error type of the program, in util/ so that every layer may throw them. Errors travel as
// exceptions from the core to src/cli, which alone prints them and chooses the
// exit code. The core never prints and never exits.
#pragma once

#include <stdexcept>
#include <string>

namespace deltri {

// Something wrong with an input file. what() is "file:line: message" (line omitted when 0).
class InputError : public std::runtime_error {
 public:
  InputError(const std::string& file, long line, const std::string& message)
      : std::runtime_error(format(file, line, message)), file_(file), line_(line) {}
  const std::string& file() const { return file_; }
  long line() const { return line_; }

 private:
  static std::string format(const std::string& file, long line, const std::string& message) {
    return line > 0 ? file + ":" + std::to_string(line) + ": " + message : file + ": " + message;
  }
  std::string file_;
  long line_;
};

// A bad command line. what() is "switch: message".
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A switch value Triangle refuses too (-a0, -r with -I): Triangle's exit status 1, not the 2 of
// other bad switches (Triangle ignores those).
class RefusedSwitchError : public UsageError {
 public:
  using UsageError::UsageError;
};

// An output file could not be written. what() is "file: message".
class OutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A job that cannot fit in the memory available: what() says what was asked and what it would
// need, before any of it is attempted.
class MemoryError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace deltri
