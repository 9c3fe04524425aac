#include "io/file_text.h"

#include <sys/stat.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <system_error>
#include <utility>

#include "util/errors.h"
#include "util/run_both.h"


namespace deltri {
namespace {

// Below this a second reading thread costs more than it saves.
constexpr std::size_t kParallelReadBytes = std::size_t{4} << 20;

struct FileCloser {
  void operator()(std::FILE* f) const { std::fclose(f); }
};
using FileHandle = std::unique_ptr<std::FILE, FileCloser>;

[[noreturn]] void fail_read(const std::string& name, int error) {
  throw InputError(name, 0, std::string("read error: ") + (error ? std::strerror(error) : "unexpected end of file"));
}

// The number of the line holding byte `at`.
long line_of(const char* data, std::size_t at) {
  return 1 + static_cast<long>(std::count(data, data + at, '\n'));
}

// Where the first line with data (not blank, not a '#' comment) ends, if its first character is
// present in [0, size) and cannot start a number: every format read through here (.node, .poly,
// .ele, .area) begins with a count. Then reading on is pointless, and for an endless stream
// (`yes garbage`) it would never end. 0 when the line is fine or not there yet.
std::size_t end_of_bad_header(const char* data, std::size_t size, bool& decided) {
  std::size_t i = size >= 3 && std::memcmp(data, "\xEF\xBB\xBF", 3) == 0 ? 3 : 0;
  while (i < size) {
    while (i < size && (data[i] == ' ' || data[i] == '\t' || data[i] == '\r')) ++i;
    if (i == size) return 0;
    if (data[i] == '\n') {
      ++i;
      continue;
    }
    if (data[i] == '#') {
      const void* nl = std::memchr(data + i, '\n', size - i);
      if (!nl) return 0;
      i = static_cast<std::size_t>(static_cast<const char*>(nl) - data) + 1;
      continue;
    }
    decided = true;
    if (std::isdigit(static_cast<unsigned char>(data[i])) || data[i] == '+' || data[i] == '-' || data[i] == '.') return 0;
    const void* nl = std::memchr(data + i, '\n', size - i);
    return nl ? static_cast<std::size_t>(static_cast<const char*>(nl) - data) + 1 : size;
  }
  return 0;
}

// Reads until end of file: works for pipes, whose size is unknown in advance. Devices and pipes
// may never end (/dev/zero, `yes garbage | deltri -`), so what arrives is checked as it arrives:
// a NUL byte (binary data) fails at once, and so does a first data line that cannot start the
// header: the text up to that line is returned for the parser to report in its usual words.
FileText read_stream(std::FILE* f, const std::string& name) {
  FileText text;
  std::size_t capacity = 0;
  bool header_decided = false;
  while (true) {
    if (text.size == capacity) {
      capacity = capacity * 2 + 65536;
      BigBytes bigger(capacity);
      if (text.size) std::memcpy(bigger.get(), text.bytes.get(), text.size);
      text.bytes = std::move(bigger);
    }
    const std::size_t got = std::fread(text.bytes.get() + text.size, 1, capacity - text.size, f);
    const std::size_t old_size = text.size;
    text.size += got;
    bool bad_header = false;
    if (!header_decided) {
      if (const std::size_t end = end_of_bad_header(text.bytes.get(), text.size, header_decided)) {
        text.size = end;
        bad_header = true;
      }
    }
    if (text.size > old_size) {
      if (const void* nul = std::memchr(text.bytes.get() + old_size, '\0', text.size - old_size)) {
        const auto at = static_cast<std::size_t>(static_cast<const char*>(nul) - text.bytes.get());
        throw InputError(name, line_of(text.bytes.get(), at), "a NUL byte: binary data, not a text file");
      }
    }
    if (bad_header) return text;
    if (got == 0) {
      if (std::ferror(f)) fail_read(name, errno);
      return text;
    }
  }
}

FileHandle open_or_throw(const std::string& path) {
  errno = 0;
  FileHandle f(std::fopen(path.c_str(), "rb"));
  if (!f) throw InputError(path, 0, errno ? std::strerror(errno) : "cannot be opened");
  return f;
}

// Reads bytes [from, to) of an open file of known size into `dest`.
void read_range(std::FILE* f, const std::string& path, char* dest, std::size_t from, std::size_t to) {
  if (from != 0 && std::fseek(f, static_cast<long>(from), SEEK_SET) != 0) fail_read(path, errno);
  if (std::fread(dest + from, 1, to - from, f) != to - from) fail_read(path, std::ferror(f) ? errno : 0);
}

// Two threads each copy half of the file: on this hardware copying out of the page cache is
// bound by page faults, which two cores take in parallel.
FileText read_sized(FileHandle f, const std::string& path, std::size_t size, int threads) {
  FileText text{BigBytes(size ? size : 1), size};
  if (size < kParallelReadBytes || threads < 2) {
    read_range(f.get(), path, text.bytes.get(), 0, size);
    return text;
  }
  run_both(
      [&] {
        FileHandle g = open_or_throw(path);
        read_range(g.get(), path, text.bytes.get(), size / 2, size);
      },
      [&] { read_range(f.get(), path, text.bytes.get(), 0, size / 2); });
  return text;
}


}  // namespace

FileText read_file_text(const std::string& path, int threads) {
  if (path == "-") return read_stream(stdin, kStandardInputName);
  std::error_code ec;
  FileHandle f(std::fopen(path.c_str(), "rb"));
  // One fstat of the open file tells a directory, a regular file and its size (asking by name had
  // taken three stat calls).
  struct stat st;
  const bool known = f && fstat(fileno(f.get()), &st) == 0;
  if ((known && S_ISDIR(st.st_mode)) || (!f && std::filesystem::is_directory(path, ec)))
    throw InputError(path, 0, "is a directory, not a file");
  if (!f) f = open_or_throw(path);  // fails again, saying why
  const std::size_t size = known && S_ISREG(st.st_mode) ? static_cast<std::size_t>(st.st_size) : 0;
  if (size == 0) return read_stream(f.get(), path);  // pipes, devices, files whose size lies
  std::setvbuf(f.get(), nullptr, _IONBF, 0);  // read in one piece into the text: no stdio buffer
  // Never mapped: a mapped file that another process shrinks faults (SIGBUS) on the lost pages,
  // where read() reports a short file, which becomes the ordinary truncated-file error.
  return read_sized(std::move(f), path, static_cast<std::size_t>(size), threads);
}

}  // namespace deltri
