// Two independent jobs at once: the one place refinement starts threads for work of its own.
#pragma once

#include <exception>
#include <system_error>
#include <thread>

namespace deltri {

// Runs first() on a second thread and second() on this one and returns when both are done; when
// no thread can be had, runs them one after the other here. An exception from either is rethrown
// here once both have stopped (second()'s if both throw).
template <class First, class Second>
void run_both(First&& first, Second&& second) {
  std::exception_ptr failure;
  std::thread worker;
  try {
    worker = std::thread([&] {
      try {
        first();
      } catch (...) {
        failure = std::current_exception();
      }
    });
  } catch (const std::system_error&) {
    first();
    second();
    return;
  }
  try {
    second();
  } catch (...) {
    worker.join();
    throw;
  }
  worker.join();
  if (failure) std::rethrow_exception(failure);
}

// run_both when `parallel`, else first() and then second() on this thread: for callers whose
// thread budget (--threads) or amount of work decides.
template <class First, class Second>
void run_both(bool parallel, First&& first, Second&& second) {
  if (parallel) {
    run_both(first, second);
  } else {
    first();
    second();
  }
}

}  // namespace deltri
