// The page warmer populates the pages just beyond the used part of an array, and no others.
#include <chrono>
#include <filesystem>
#include <cstdint>
#include <thread>
#include <vector>

#include "harness/check.h"
#include "util/big_allocator.h"
#include "util/page_warmer.h"

#ifdef __linux__
#include <sys/mman.h>
#include <unistd.h>
#endif

using namespace deltri;

#if defined(__linux__) && defined(MADV_POPULATE_WRITE)
namespace {

// Resident 4 KiB pages in [p, p + bytes), by mincore (p page-aligned).
std::size_t resident_pages(const void* p, std::size_t bytes) {
  const std::size_t pages = bytes / 4096;
  std::vector<unsigned char> in(pages);
  if (mincore(const_cast<void*>(p), bytes, in.data()) != 0) return 0;
  std::size_t n = 0;
  for (unsigned char c : in) n += c & 1;
  return n;
}

// Threads of this process, from /proc/self/task.
std::size_t threads_now() {
  std::size_t n = 0;
  std::error_code ec;
  for (std::filesystem::directory_iterator it("/proc/self/task", ec), end; !ec && it != end; it.increment(ec)) ++n;
  return n;
}

}  // namespace

// Asks `warmer` about an array using `used` bytes of `v`'s capacity and waits for [from, to) to
// become resident; returns how many of its pages are. The wait ends as soon as they are; its limit
// (30 s) is only a guard for a machine so busy that the warmer thread is not scheduled.
std::size_t warmed_pages(PageWarmer& warmer, const BigVector<std::uint32_t>& v, std::size_t used,
                         std::size_t from, std::size_t to) {
  const char* base = reinterpret_cast<const char*>(v.data());
  warmer.note(0, v.data(), used, v.capacity() * sizeof(std::uint32_t));
  for (int i = 0; i < 6000 && resident_pages(base + from, to - from) < (to - from) / 4096; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  return resident_pages(base + from, to - from);
}

TEST(page_warmer_populates_the_next_huge_page_shortly_before_use_and_no_further) {
  constexpr std::size_t huge = PageWarmer::kHugePage;
  BigVector<std::uint32_t> v;
  v.reserve(16u << 20);  // 64 MiB of untouched capacity, starting on a huge-page boundary
  const std::size_t capacity = v.capacity() * sizeof(std::uint32_t);
  const char* base = reinterpret_cast<const char*>(v.data());
  CHECK_EQ(reinterpret_cast<std::uintptr_t>(base) % huge, 0u);
  PageWarmer warmer(true);
  // Far from the end of the first huge page: nothing beyond it is populated. (Load can only make
  // this pass wrongly, never fail: the warmer may not have run yet.)
  warmer.note(0, v.data(), 4096, capacity);
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  CHECK_EQ(resident_pages(base + huge, capacity - huge), 0u);
  // Within kLead of it: the second huge page is populated, and nothing after it.
  const std::size_t used = huge - PageWarmer::kLead / 2;
  CHECK_EQ(warmed_pages(warmer, v, used, huge, 2 * huge), huge / 4096);
  CHECK_EQ(resident_pages(base + 2 * huge, capacity - 2 * huge), 0u);
}

// A small run pays for no thread: the warmer starts its own only when an array nears the end of
// its first huge page, where warming first has something to do.
TEST(page_warmer_starts_its_thread_only_when_an_array_nears_its_second_huge_page) {
  constexpr std::size_t huge = PageWarmer::kHugePage;
  BigVector<std::uint32_t> v;
  v.reserve(16u << 20);
  const std::size_t capacity = v.capacity() * sizeof(std::uint32_t);
  const std::size_t before = threads_now();
  CHECK(before > 0u);
  PageWarmer warmer(true);
  for (std::size_t used = 4096; used < PageWarmer::kStartUsed; used += 64 << 10) warmer.note(0, v.data(), used, capacity);
  CHECK_EQ(threads_now(), before);
  warmer.note(0, v.data(), huge - PageWarmer::kLead / 2, capacity);
  CHECK_EQ(threads_now(), before + 1);
}
#endif

TEST(page_warmer_disabled_does_nothing_and_values_survive) {
  BigVector<std::uint32_t> v(4u << 20, 7u);
  PageWarmer warmer(false);
  warmer.note(0, v.data(), v.size() * sizeof(std::uint32_t), v.capacity() * sizeof(std::uint32_t));
  std::uint64_t sum = 0;
  for (std::uint32_t x : v) sum += x;
  CHECK_EQ(sum, std::uint64_t{7} * (4u << 20));
}
