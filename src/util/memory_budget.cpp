#include "util/memory_budget.h"

#include <fcntl.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>
#include <string_view>

namespace deltri {
namespace {

double limit_of(int resource) {
  rlimit limit{};
  if (getrlimit(resource, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) return HUGE_VAL;
  return static_cast<double>(limit.rlim_cur);
}

// The first line of a file, without its newline ("" if it cannot be read). open and read into a
// buffer on the stack: stdio would add an fstat, a FILE and a 4 KiB buffer from the heap (whose
// first touch may be a page fault), in every run that refines.
std::string first_line(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return {};
  char buffer[4096];
  const ssize_t got = ::read(fd, buffer, sizeof buffer);
  ::close(fd);
  if (got <= 0) return {};
  const std::string_view text(buffer, static_cast<std::size_t>(got));
  return std::string(text.substr(0, text.find('\n')));
}

// cgroup v2's memory.max of this process's group ("max" or absent: no limit).
double cgroup_limit() {
  const std::string line = first_line("/proc/self/cgroup");
  if (line.rfind("0::", 0) != 0) return HUGE_VAL;
  const std::string max = first_line("/sys/fs/cgroup" + line.substr(3) + "/memory.max");
  char* end = nullptr;
  const double bytes = std::strtod(max.c_str(), &end);
  return end != max.c_str() ? bytes : HUGE_VAL;
}

}  // namespace

double memory_budget() {
  const long pages = sysconf(_SC_PHYS_PAGES);
  const long page_size = sysconf(_SC_PAGE_SIZE);
  double budget = pages > 0 && page_size > 0 ? static_cast<double>(pages) * static_cast<double>(page_size) : HUGE_VAL;
  budget = std::min({budget, limit_of(RLIMIT_AS), limit_of(RLIMIT_DATA), cgroup_limit()});
  return std::isfinite(budget) ? budget : 0.0;
}

}  // namespace deltri
