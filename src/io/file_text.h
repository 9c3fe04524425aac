// Whole-file input. Every reader works on the full text in memory, so parsing never waits on I/O
// and a file read from standard input behaves exactly like one read from disk.
#pragma once

#include <cstddef>
#include <string>

#include "util/big_allocator.h"

namespace deltri {

// Raw bytes; not a std::string because zero-filling a large buffer before reading into it costs
// as much as a third of the read.
struct FileText {
  BigBytes bytes;
  std::size_t size = 0;
};

// How messages name standard input (the path "-").
inline constexpr const char* kStandardInputName = "standard input";

// The bytes of `path`, or of standard input when `path` is "-". Throws InputError(path, 0, ...)
// when the file cannot be read (missing, a directory, a read error).
FileText read_file_text(const std::string& path);

}  // namespace deltri
