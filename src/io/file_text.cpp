#include "io/file_text.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <system_error>
#include <thread>
#include <utility>

#include "pslg/errors.h"

#ifdef __linux__
#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>
#endif

namespace deltri {
namespace {

// Below this a second reading thread costs more than it saves.
constexpr std::size_t kParallelReadBytes = std::size_t{4} << 20;
// From this size a file is mapped rather than copied, where the system allows.
[[maybe_unused]] constexpr std::size_t kMapBytes = std::size_t{4} << 20;

struct FileCloser {
  void operator()(std::FILE* f) const { std::fclose(f); }
};
using FileHandle = std::unique_ptr<std::FILE, FileCloser>;

[[noreturn]] void fail_read(const std::string& name, int error) {
  throw InputError(name, 0, std::string("read error: ") + (error ? std::strerror(error) : "unexpected end of file"));
}

// Reads until end of file: works for pipes, whose size is unknown in advance.
FileText read_stream(std::FILE* f, const std::string& name) {
  FileText text;
  std::size_t capacity = 0;
  while (true) {
    if (text.size == capacity) {
      capacity = capacity * 2 + 65536;
      BigBytes bigger(capacity);
      if (text.size) std::memcpy(bigger.get(), text.bytes.get(), text.size);
      text.bytes = std::move(bigger);
    }
    const std::size_t got = std::fread(text.bytes.get() + text.size, 1, capacity - text.size, f);
    text.size += got;
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
FileText read_sized(FileHandle f, const std::string& path, std::size_t size) {
  FileText text{BigBytes(size ? size : 1), size, {}};
  if (size < kParallelReadBytes) {
    read_range(f.get(), path, text.bytes.get(), 0, size);
    return text;
  }
  std::exception_ptr second_failed;
  std::thread second([&] {
    try {
      FileHandle g = open_or_throw(path);
      read_range(g.get(), path, text.bytes.get(), size / 2, size);
    } catch (...) {
      second_failed = std::current_exception();
    }
  });
  try {
    read_range(f.get(), path, text.bytes.get(), 0, size / 2);
  } catch (...) {
    second.join();
    throw;
  }
  second.join();
  if (second_failed) std::rethrow_exception(second_failed);
  return text;
}

#ifdef __linux__
// Maps a regular file of `size` bytes; false (and `text` untouched) when that is not possible or
// the file's size changed since it was measured, in which case the caller reads it instead. Pages
// are faulted in by the threads that parse them, not in advance.
bool map_file(const std::string& path, std::size_t size, FileText& text) {
  const int fd = open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return false;
  struct stat st;
  void* p = MAP_FAILED;
  if (fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && static_cast<std::size_t>(st.st_size) == size)
    p = mmap(nullptr, size, PROT_READ, MAP_PRIVATE, fd, 0);
  close(fd);  // the mapping keeps the file
  if (p == MAP_FAILED) return false;
  text.mapped = MappedFile(static_cast<const char*>(p), size);
  text.size = size;
  return true;
}
#endif

}  // namespace

MappedFile& MappedFile::operator=(MappedFile&& other) noexcept {
  if (this != &other) {
    release();
    data_ = std::exchange(other.data_, nullptr);
    size_ = other.size_;
  }
  return *this;
}

MappedFile::~MappedFile() { release(); }

void MappedFile::release() noexcept {
#ifdef __linux__
  if (data_) munmap(const_cast<char*>(data_), size_);
#endif
  data_ = nullptr;
}

FileText read_file_text(const std::string& path) {
  if (path == "-") return read_stream(stdin, kStandardInputName);
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw InputError(path, 0, "is a directory, not a file");
  FileHandle f = open_or_throw(path);
  const auto size = std::filesystem::is_regular_file(path, ec) ? std::filesystem::file_size(path, ec) : 0;
  if (ec || size == 0) return read_stream(f.get(), path);  // pipes, devices, files whose size lies
#ifdef __linux__
  // A file that shrinks while it is mapped would fault (SIGBUS) where a read would report a short
  // file; input files changing during a run are not something a mesher can defend against anyway.
  FileText mapped;
  if (size >= kMapBytes && map_file(path, static_cast<std::size_t>(size), mapped)) return mapped;
#endif
  return read_sized(std::move(f), path, static_cast<std::size_t>(size));
}

}  // namespace deltri
