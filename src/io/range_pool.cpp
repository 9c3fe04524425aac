#include "io/range_pool.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <string>
#include <utility>

namespace deltri {

// One file's ranges. Ranges are claimed in order and never more than `in_flight` ahead of the
// next one to write (one per writing thread, so no thread waits for a slot, and the buffers, about
// 100 KB each, leave the peak memory as it was: docs/benchmarks.md); whichever thread finishes
// the next range writes it and any ready after it.
class RangeJob {
 public:
  RangeJob(ByteSink& sink, const LineRanges& ranges, std::size_t in_flight)
      : sink_(sink), ranges_(ranges), count_(ranges.count()), in_flight_(in_flight), slots_(in_flight),
        ready_(in_flight, 0) {}

  // Formats (and writes) ranges until none is left to claim.
  void work() {
    while (step()) {}
  }
  bool open() const { return open_.load(); }
  // Waits until every claimed range is written or the job failed; throws the failure.
  void finish() {
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [&] { return busy_ == 0; });
    if (error_) std::rethrow_exception(error_);
  }
  std::size_t visitors = 0;  // helpers inside work(); guarded by the pool's mutex

 private:
  bool step();
  void format(std::size_t r, std::string& text) const {
    text.clear();
    StringSink sink(text);
    TextWriter out(sink);
    ranges_.format(out, ranges_.begin(r), ranges_.end(r));
    out.finish();
  }
  void drain(std::unique_lock<std::mutex>& lock);
  void fail(std::exception_ptr e) {
    if (!error_) error_ = std::move(e);
    open_ = false;
  }

  ByteSink& sink_;
  const LineRanges& ranges_;
  const std::size_t count_;
  std::atomic<bool> open_{true};
  std::mutex mutex_;
  std::condition_variable changed_;
  std::size_t next_claim_ = 0, next_write_ = 0, busy_ = 0;
  bool writing_ = false;
  const std::size_t in_flight_;
  std::vector<std::string> slots_;
  std::vector<char> ready_;
  std::vector<std::string> spares_;
  std::exception_ptr error_;
};

bool RangeJob::step() {
  std::unique_lock lock(mutex_);
  changed_.wait(lock, [&] { return error_ || next_claim_ == count_ || next_claim_ < next_write_ + in_flight_; });
  if (error_ || next_claim_ == count_) {
    open_ = false;
    return false;
  }
  const std::size_t r = next_claim_++;
  if (next_claim_ == count_) open_ = false;
  ++busy_;
  std::string text;
  if (!spares_.empty()) {
    text = std::move(spares_.back());
    spares_.pop_back();
  }
  lock.unlock();
  std::exception_ptr failed;
  try {
    format(r, text);
  } catch (...) {
    failed = std::current_exception();
  }
  lock.lock();
  if (failed) {
    fail(failed);
  } else {
    slots_[r % in_flight_] = std::move(text);
    ready_[r % in_flight_] = 1;
    if (!writing_) drain(lock);
  }
  --busy_;
  changed_.notify_all();
  return !failed;
}

// Writes the ready ranges from next_write_ on, the lock released while writing; one thread at a
// time (writing_), so the file gets the ranges in order.
void RangeJob::drain(std::unique_lock<std::mutex>& lock) {
  writing_ = true;
  while (!error_ && ready_[next_write_ % in_flight_]) {
    const std::size_t slot = next_write_ % in_flight_;
    std::string text = std::move(slots_[slot]);
    ready_[slot] = 0;
    lock.unlock();
    std::exception_ptr failed;
    try {
      sink_.write(text.data(), text.size());
    } catch (...) {
      failed = std::current_exception();
    }
    lock.lock();
    if (failed) {
      fail(failed);
      break;
    }
    ++next_write_;
    spares_.push_back(std::move(text));  // its capacity is kept for a later range
    changed_.notify_all();
  }
  writing_ = false;
}

void RangePool::write(ByteSink& sink, const LineRanges& ranges) {
  RangeJob job(sink, ranges, workers_);
  {
    std::lock_guard lock(mutex_);
    jobs_.push_back(&job);
  }
  changed_.notify_all();
  job.work();
  {
    std::unique_lock lock(mutex_);
    jobs_.erase(std::find(jobs_.begin(), jobs_.end(), &job));
    changed_.wait(lock, [&] { return job.visitors == 0; });
  }
  job.finish();
}

RangeJob* RangePool::open_job() {
  for (RangeJob* job : jobs_)
    if (job->open()) return job;
  return nullptr;
}

void RangePool::absent() {
  {
    std::lock_guard lock(mutex_);
    --working_;
  }
  changed_.notify_all();
}

void RangePool::help() {
  std::unique_lock lock(mutex_);
  --working_;
  changed_.notify_all();
  while (true) {
    if (RangeJob* job = open_job()) {
      ++job->visitors;
      lock.unlock();
      job->work();
      lock.lock();
      --job->visitors;
      changed_.notify_all();
      continue;
    }
    if (working_ == 0) return;
    changed_.wait(lock);
  }
}

}  // namespace deltri
