#include "util/memory_budget.h"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <string>

namespace deltri {
namespace {

double limit_of(int resource) {
  rlimit limit{};
  if (getrlimit(resource, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) return HUGE_VAL;
  return static_cast<double>(limit.rlim_cur);
}

// cgroup v2's memory.max of this process's group ("max" or absent: no limit).
double cgroup_limit() {
  std::ifstream group("/proc/self/cgroup");
  std::string line;
  if (!std::getline(group, line) || line.rfind("0::", 0) != 0) return HUGE_VAL;
  std::ifstream max("/sys/fs/cgroup" + line.substr(3) + "/memory.max");
  double bytes = HUGE_VAL;
  if (max >> bytes) return bytes;
  return HUGE_VAL;
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
