// Faulting in the pages of growing arrays ahead of their use, on a second thread.
//
// Refinement appends triangles and vertices to arrays whose capacity was reserved up front but
// never touched (so a generous guess costs no resident memory). Each first touch of a 2 MiB page
// then stops refinement while the kernel zeroes it: on the 45x45-hole workload about 6% of the
// run went to that. A PageWarmer, told now and then how far each array is used, asks the kernel
// on its own thread to populate the next huge page of each (madvise MADV_POPULATE_WRITE), so the
// pages are there when the appends arrive. The contents of memory are never read or written, so
// there is nothing to race on. Only the huge page after the one in use is populated, and only
// shortly before it is needed, so the resident memory stays about what the arrays use. Where the
// advice or threads are unavailable, nothing happens and the arrays fault in as before.
#pragma once

#include <condition_variable>
#include <cstddef>
#include <mutex>
#include <thread>
#include <vector>

namespace deltri {

class PageWarmer {
 public:
  // Populating works in huge pages (2 MiB): the next one is asked for once the used part of an
  // array comes within kLead of it, some milliseconds of refinement before the appends arrive,
  // so an array ends with an extra page resident only when it stops that close to one.
  static constexpr std::size_t kHugePage = std::size_t{2} << 20;
  static constexpr std::size_t kLead = std::size_t{128} << 10;
  // The thread starts only once some array comes within kLead of the end of its first huge page,
  // where warming first reaches past it: a small run's pages fault in within microseconds, while
  // starting and joining a thread costs such a run more than all of them (and, on a busy
  // machine, a wait for the scheduler).
  static constexpr std::size_t kStartUsed = kHugePage - kLead;
  // No thread (and no effect) unless `enabled`.
  explicit PageWarmer(bool enabled);
  ~PageWarmer();
  PageWarmer(const PageWarmer&) = delete;
  PageWarmer& operator=(const PageWarmer&) = delete;

  // Array `slot` (0 .. kSlots-1, one per array) starts at `data`, uses `used` bytes and owns
  // `capacity`. Cheap when nothing new is due: call it as often as convenient.
  void note(unsigned slot, const void* data, std::size_t used, std::size_t capacity);

  static constexpr unsigned kSlots = 8;

 private:
  struct Range {
    char* from;
    std::size_t bytes;
  };
  struct Watched {
    const char* data = nullptr;
    std::size_t warmed = 0;  // bytes from data asked for so far
  };
  void work();
  bool enabled_;
  Watched watched_[kSlots];
  std::mutex mutex_;
  std::condition_variable wake_;
  std::vector<Range> pending_;  // guarded by mutex_
  bool stopping_ = false;       // guarded by mutex_
  std::thread worker_;
};

}  // namespace deltri
