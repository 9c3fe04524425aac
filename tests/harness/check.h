// A small standard-library test harness: TEST(name) registers a function, CHECK* record failures
// without stopping the test, REQUIRE* stop it. main() lives in check.cpp and runs every test, or
// only those whose names contain argv[1].
#pragma once
#include <cmath>
#include <functional>
#include <sstream>
#include <string>

namespace harness {

struct Registration {
  Registration(const char* name, std::function<void()> body);
};

void fail(const char* file, int line, const std::string& what);
struct Abort {};  // thrown by REQUIRE to end the current test

template <class A, class B>
std::string describe(const A& a, const B& b) {
  std::ostringstream out;
  out.precision(17);
  out << a << " vs " << b;
  return out.str();
}

}  // namespace harness

#define HARNESS_CAT2(a, b) a##b
#define HARNESS_CAT(a, b) HARNESS_CAT2(a, b)
#define TEST(name)                                                                  \
  static void HARNESS_CAT(test_body_, name)();                                      \
  static harness::Registration HARNESS_CAT(test_reg_, name)(#name,                  \
                                                            HARNESS_CAT(test_body_, name)); \
  static void HARNESS_CAT(test_body_, name)()

#define CHECK(cond) \
  do { if (!(cond)) harness::fail(__FILE__, __LINE__, "CHECK(" #cond ")"); } while (0)
#define REQUIRE(cond)                                                    \
  do {                                                                   \
    if (!(cond)) {                                                       \
      harness::fail(__FILE__, __LINE__, "REQUIRE(" #cond ")");           \
      throw harness::Abort{};                                            \
    }                                                                    \
  } while (0)
#define CHECK_EQ(a, b)                                                                   \
  do {                                                                                   \
    const auto& check_a_ = (a);                                                          \
    const auto& check_b_ = (b);                                                          \
    if (!(check_a_ == check_b_))                                                         \
      harness::fail(__FILE__, __LINE__,                                                  \
                    "CHECK_EQ(" #a ", " #b "): " + harness::describe(check_a_, check_b_)); \
  } while (0)
#define CHECK_NEAR(a, b, tol)                                                            \
  do {                                                                                   \
    const double check_a_ = (a), check_b_ = (b);                                         \
    if (!(std::fabs(check_a_ - check_b_) <= (tol)))                                      \
      harness::fail(__FILE__, __LINE__,                                                  \
                    "CHECK_NEAR(" #a ", " #b "): " + harness::describe(check_a_, check_b_)); \
  } while (0)
#define CHECK_THROWS(expr)                                                   \
  do {                                                                       \
    bool check_threw_ = false;                                               \
    try { (void)(expr); } catch (...) { check_threw_ = true; }               \
    if (!check_threw_) harness::fail(__FILE__, __LINE__, "CHECK_THROWS(" #expr ")"); \
  } while (0)
