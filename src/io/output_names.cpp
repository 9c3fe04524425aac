#include "io/output_names.h"

#include <array>
#include <string_view>

namespace deltri {
namespace {

std::size_t file_name_start(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? 0 : slash + 1;
}

bool all_digits(std::string_view s) {
  if (s.empty()) return false;
  for (char c : s)
    if (c < '0' || c > '9') return false;
  return true;
}

// Decimal increment on the text, so no iteration number is too long; leading zeros go, as
// Triangle reads the number and prints it back.
std::string incremented(std::string_view digits) {
  std::string n(digits);
  std::size_t i = n.size();
  while (i > 0 && n[i - 1] == '9') n[--i] = '0';
  if (i == 0) n.insert(n.begin(), '1');
  else ++n[i - 1];
  const std::size_t nonzero = n.find_first_not_of('0');
  return n.substr(nonzero == std::string::npos ? n.size() - 1 : nonzero);
}

}  // namespace

std::string input_base(const std::string& path, std::string* extension) {
  static constexpr std::array<std::string_view, 4> kKnown{"node", "poly", "ele", "area"};
  const std::size_t dot = path.find_last_of('.');
  if (extension) extension->clear();
  if (dot == std::string::npos || dot <= file_name_start(path)) return path;
  const std::string_view ext = std::string_view(path).substr(dot + 1);
  for (std::string_view known : kKnown) {
    if (ext != known) continue;
    if (extension) *extension = std::string(ext);
    return path.substr(0, dot);
  }
  return path;
}

std::string output_base(const std::string& base, bool no_iteration_number) {
  if (no_iteration_number) return base;
  const std::size_t dot = base.find_last_of('.');
  if (dot != std::string::npos && dot > file_name_start(base) && all_digits(std::string_view(base).substr(dot + 1)))
    return base.substr(0, dot + 1) + incremented(std::string_view(base).substr(dot + 1));
  return base + ".1";
}

}  // namespace deltri
