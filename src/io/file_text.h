// Whole-file input. Every reader works on the full text in memory, so parsing never waits on I/O
// and a file read from standard input behaves exactly like one read from disk.
#pragma once

#include <cstddef>
#include <string>

#include "util/big_allocator.h"

namespace deltri {

// The text of a file, its bytes read into memory. Not a std::string because zero-filling a large
// buffer before reading into it costs as much as a third of the read. Never a mapping of the file:
// a mapped file that shrinks under us faults (SIGBUS), where read() reports the short file.
struct FileText {
  BigBytes bytes;
  std::size_t size = 0;
  const char* data() const { return bytes.get(); }
};

// The readers' thread bound when the caller gives none: a large file is read in two halves.
inline constexpr int kReadThreads = 2;

// How messages name standard input (the path "-").
inline constexpr const char* kStandardInputName = "standard input";

// The bytes of `path`, or of standard input when `path` is "-". Throws InputError(path, 0, ...)
// when the file cannot be read (missing, a directory, a read error). A large file is read by two
// threads when `threads` is 2 or more (--threads), else by the calling thread alone.
FileText read_file_text(const std::string& path, int threads = kReadThreads);

}  // namespace deltri
