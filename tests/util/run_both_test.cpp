// run_both and run_halves (util/run_both.h): every job runs exactly once, on the thread the
// header says, and an exception reaches the caller only after both jobs have stopped.
#include <atomic>
#include <chrono>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "harness/check.h"
#include "mesh/ids.h"
#include "util/run_both.h"

using namespace deltri;

namespace {

struct Visit {
  std::size_t from = 0, to = 0;
  bool seen = false;
  std::thread::id thread;
};

// run_halves over [begin, end): each index visited once, half 0 ending where half 1 starts (at
// the middle, rounded down), the upper half on another thread when parallel.
void check_halves(std::size_t begin, std::size_t end, bool parallel) {
  std::vector<std::atomic<int>> visits(end + 1);
  Visit half[2];
  run_halves(parallel, begin, end, [&](std::size_t from, std::size_t to, int h) {
    half[h] = {from, to, true, std::this_thread::get_id()};
    for (std::size_t i = from; i < to; ++i) ++visits[i];
  });
  for (std::size_t i = 0; i <= end; ++i) CHECK_EQ(visits[i].load(), i >= begin && i < end ? 1 : 0);
  CHECK(half[0].seen && half[1].seen);
  CHECK_EQ(half[0].from, begin);
  CHECK_EQ(half[0].to, begin + (end - begin) / 2);
  CHECK_EQ(half[1].from, half[0].to);
  CHECK_EQ(half[1].to, end);
  CHECK(half[0].thread == std::this_thread::get_id());
  CHECK_EQ(half[1].thread != std::this_thread::get_id(), parallel);
}

}  // namespace

TEST(run_halves_visits_every_index_once_in_two_halves) {
  for (const bool parallel : {false, true})
    for (const auto& [begin, end] : std::vector<std::pair<std::size_t, std::size_t>>{{0, 0}, {0, 1}, {0, 7}, {3, 4}, {5, 1000}})
      check_halves(begin, end, parallel);
}

TEST(run_halves_splits_strong_ids) {
  EdgeRef seen[2][2];
  run_halves(true, EdgeRef{10}, EdgeRef{21}, [&](EdgeRef from, EdgeRef to, int h) {
    seen[h][0] = from;
    seen[h][1] = to;
  });
  CHECK(seen[0][0] == EdgeRef{10} && seen[0][1] == EdgeRef{15});
  CHECK(seen[1][0] == EdgeRef{15} && seen[1][1] == EdgeRef{21});
}

TEST(run_both_runs_first_then_second_here_when_not_parallel) {
  std::vector<int> order;
  std::thread::id where[2];
  run_both(
      false, [&] { order.push_back(1), where[0] = std::this_thread::get_id(); },
      [&] { order.push_back(2), where[1] = std::this_thread::get_id(); });
  CHECK(order == std::vector<int>({1, 2}));
  CHECK(where[0] == std::this_thread::get_id() && where[1] == std::this_thread::get_id());
}

TEST(run_both_rethrows_after_both_jobs_have_stopped) {
  // One job throws at once, the other takes a while: the exception must arrive only once the slow
  // job has finished too.
  for (const int thrower : {1, 2}) {
    std::atomic<bool> slow_done{false};
    const auto job = [&](int which) {
      if (which == thrower) throw std::runtime_error("job " + std::to_string(which));
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
      slow_done = true;
    };
    std::string caught;
    try {
      run_both([&] { job(1); }, [&] { job(2); });
    } catch (const std::runtime_error& e) {
      caught = e.what();
    }
    CHECK_EQ(caught, "job " + std::to_string(thrower));
    CHECK(slow_done.load());
  }
}

TEST(run_both_prefers_the_second_jobs_exception_when_both_throw) {
  std::string caught;
  try {
    run_both([] { throw std::runtime_error("first"); }, [] { throw std::runtime_error("second"); });
  } catch (const std::runtime_error& e) {
    caught = e.what();
  }
  CHECK_EQ(caught, std::string("second"));
}
