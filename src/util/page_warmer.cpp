#include "util/page_warmer.h"

#include <algorithm>
#include <cstdint>
#include <system_error>

#ifdef __linux__
#include <sys/mman.h>
#endif

namespace deltri {
namespace {

#if defined(__linux__) && defined(MADV_POPULATE_WRITE)
constexpr bool kAvailable = true;
constexpr std::size_t kPage = 4096;

// Populates the whole pages inside [from, from + bytes). Failure (an old kernel, a range freed in
// the meantime by a reallocation) leaves the pages to fault in on use, as without the warmer.
void populate(char* from, std::size_t bytes) {
  const auto start = (reinterpret_cast<std::uintptr_t>(from) + kPage - 1) & ~std::uintptr_t{kPage - 1};
  const auto end = (reinterpret_cast<std::uintptr_t>(from) + bytes) & ~std::uintptr_t{kPage - 1};
  if (end > start) madvise(reinterpret_cast<void*>(start), end - start, MADV_POPULATE_WRITE);
}
#else
constexpr bool kAvailable = false;
void populate(char*, std::size_t) {}
#endif

}  // namespace

PageWarmer::PageWarmer(bool enabled) : enabled_(enabled && kAvailable) {}

PageWarmer::~PageWarmer() {
  if (!worker_.joinable()) return;
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_one();
  worker_.join();
}

void PageWarmer::note(unsigned slot, const void* data, std::size_t used, std::size_t capacity) {
  if (!enabled_ || slot >= kSlots) return;
  if (!worker_.joinable()) {
    if (used < kStartUsed) return;
    try {
      worker_ = std::thread([this] { work(); });
    } catch (const std::system_error&) {
      enabled_ = false;  // no thread to be had: the pages fault in on use
      return;
    }
  }
  Watched& w = watched_[slot];
  const char* base = static_cast<const char*>(data);
  if (w.data != base) w = Watched{base, 0};  // a new block (the array was reallocated)
  if (used + kLead <= w.warmed || w.warmed >= capacity) return;
  // Page boundaries are absolute addresses (big blocks start on one; others need not).
  const auto at = reinterpret_cast<std::uintptr_t>(base);
  const std::uintptr_t end = (at + used + kLead + kHugePage - 1) & ~std::uintptr_t{kHugePage - 1};
  // Past the block's last whole huge page the pages are small (big_allocator.h): there only the
  // next 2 kLead bytes are asked for, so a block that ends partly used wastes little.
  const std::uintptr_t last_huge = (at + capacity) & ~std::uintptr_t{kHugePage - 1};
  const std::size_t to = end <= last_huge ? static_cast<std::size_t>(end - at)
                                           : std::min(capacity, used + 2 * kLead);
  const std::size_t from = std::max(w.warmed, used);
  w.warmed = to;
  if (to <= from) return;
  const Range range{const_cast<char*>(base) + from, to - from};
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    pending_.push_back(range);
  }
  wake_.notify_one();
}

void PageWarmer::work() {
  std::vector<Range> batch;
  for (;;) {
    {
      std::unique_lock<std::mutex> lock(mutex_);
      wake_.wait(lock, [this] { return stopping_ || !pending_.empty(); });
      if (stopping_) return;
      batch.swap(pending_);
    }
    for (const Range& r : batch) populate(r.from, r.bytes);
    batch.clear();
  }
}

}  // namespace deltri
