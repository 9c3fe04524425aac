#include "harness/check.h"

#include <cstdio>
#include <cstring>
#include <exception>
#include <vector>

namespace harness {
namespace {

struct Test {
  const char* name;
  std::function<void()> body;
};

std::vector<Test>& registry() {
  static std::vector<Test> tests;
  return tests;
}

int failures_in_current_test = 0;

}  // namespace

Registration::Registration(const char* name, std::function<void()> body) {
  registry().push_back({name, std::move(body)});
}

void fail(const char* file, int line, const std::string& what) {
  if (++failures_in_current_test > 20) return;  // the first failures say enough
  std::fprintf(stderr, "%s:%d: FAILED %s\n", file, line, what.c_str());
}

}  // namespace harness

int main(int argc, char** argv) {
  const char* filter = argc > 1 ? argv[1] : nullptr;
  int passed = 0, failed = 0;
  for (auto& test : harness::registry()) {
    if (filter && !std::strstr(test.name, filter)) continue;
    harness::failures_in_current_test = 0;
    try {
      test.body();
    } catch (const harness::Abort&) {
    } catch (const std::exception& e) {
      harness::fail(test.name, 0, std::string("unexpected exception: ") + e.what());
    }
    if (harness::failures_in_current_test == 0) {
      ++passed;
    } else {
      ++failed;
      std::fprintf(stderr, "test %s failed\n", test.name);
    }
  }
  std::printf("%d passed, %d failed\n", passed, failed);
  return failed == 0 && passed > 0 ? 0 : 1;
}
