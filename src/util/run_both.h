// Two independent jobs at once, and a range's two halves at once: where the pipeline's threads
// start, but for the writers' pool (io/output_set.cpp) and the page warmer's worker.
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

// Splits [begin, end) at its middle and calls part(from, to, half) for each half: the upper
// (half 1) on a second thread and the lower (half 0) on this one when `parallel`, else both here.
// The halves must not depend on each other; what each finds is kept by half and combined as one
// pass over the whole range would have found it, so that the answer is the same for any threads.
template <class Index, class Part>
void run_halves(bool parallel, Index begin, Index end, Part&& part) {
  const Index middle{begin + (end - begin) / 2};
  run_both(parallel, [&] { part(middle, end, 1); }, [&] { part(begin, middle, 0); });
}

}  // namespace deltri
