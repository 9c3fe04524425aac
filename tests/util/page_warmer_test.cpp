// The page warmer populates the pages just beyond the used part of an array, and no others.
#include <chrono>
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

}  // namespace

TEST(page_warmer_populates_ahead_of_use_and_no_further) {
  BigVector<std::uint32_t> v;
  v.reserve(16u << 20);  // 64 MiB of untouched capacity
  v.resize(1024);         // 4 KiB used
  const std::size_t capacity = v.capacity() * sizeof(std::uint32_t);
  const char* base = reinterpret_cast<const char*>(v.data());
  const std::size_t ahead = PageWarmer::kAhead;
  CHECK(resident_pages(base + ahead, capacity - ahead) == 0);
  {
    PageWarmer warmer(true);
    warmer.note(0, v.data(), v.size() * sizeof(std::uint32_t), capacity);
    // The work is asynchronous; the destructor would drop a request not yet taken.
    for (int i = 0; i < 200 && resident_pages(base + 8192, ahead - 8192) < (ahead - 8192) / 4096; ++i)
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  CHECK_EQ(resident_pages(base + 8192, ahead - 8192), (ahead - 8192) / 4096);
  // Beyond kAhead (plus a huge page the kernel may round up to) nothing was touched.
  const std::size_t beyond = ahead + (std::size_t{2} << 20);
  CHECK_EQ(resident_pages(base + beyond, capacity - beyond), 0u);
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
