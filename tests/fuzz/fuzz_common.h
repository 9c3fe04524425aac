// Shared by the libFuzzer targets: the readers take paths, so each input goes through a file in a
// private directory (on /dev/shm when there is one: no disk traffic per execution).
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <sys/stat.h>
#include <unistd.h>

namespace deltri::fuzz {

inline const std::string& scratch_dir() {
  static const std::string dir = [] {
    char shm[] = "/dev/shm/deltri-fuzz-XXXXXX";
    char tmp[] = "/tmp/deltri-fuzz-XXXXXX";
    const char* d = mkdtemp(shm);
    if (!d) d = mkdtemp(tmp);
    if (!d) __builtin_trap();
    return std::string(d);
  }();
  return dir;
}

// Writes `size` bytes to scratch_dir()/name (one level of subdirectory allowed) and returns the path.
inline std::string write_input(const std::string& name, const std::uint8_t* data, std::size_t size) {
  const std::string path = scratch_dir() + "/" + name;
  const std::size_t slash = name.rfind('/');
  if (slash != std::string::npos) mkdir((scratch_dir() + "/" + name.substr(0, slash)).c_str(), 0700);
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) __builtin_trap();
  if (size && std::fwrite(data, 1, size, f) != size) __builtin_trap();
  if (std::fclose(f) != 0) __builtin_trap();
  return path;
}

// Every target reads a selector byte first (which reader, which switches), then the file text.
// False for inputs that are empty or beyond the size the targets accept.
inline bool take_selector(const std::uint8_t*& data, std::size_t& size, std::uint8_t& selector) {
  if (size < 1 || size > 8192) return false;
  selector = data[0];
  ++data;
  --size;
  return true;
}

}  // namespace deltri::fuzz
