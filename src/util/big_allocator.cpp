#include "util/big_allocator.h"

#include <cstdint>

#ifdef __GLIBC__
#include <malloc.h>
#endif
#ifdef __linux__
#include <sys/mman.h>
#include <unistd.h>
#endif

namespace deltri {
namespace {

#ifdef __linux__
constexpr std::size_t kHugePage = std::size_t{2} << 20;

// Whole small pages only: a last partial huge page stays in small pages instead of adding up to
// 2 MiB of resident memory per array (which cost 3 bytes per point at the peak).
std::size_t mapped_size(std::size_t bytes) {
  const long page = sysconf(_SC_PAGESIZE);
  const std::size_t small = page > 0 ? static_cast<std::size_t>(page) : 4096;
  return (bytes + small - 1) / small * small;
}

// Maps one huge page more than needed and trims both ends, so that the block starts on a 2 MiB
// boundary. Null when mmap fails.
void* map_aligned(std::size_t size) {
  const std::size_t padded = size + kHugePage;
  void* raw = mmap(nullptr, padded, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (raw == MAP_FAILED) return nullptr;
  const auto start = reinterpret_cast<std::uintptr_t>(raw);
  const std::uintptr_t aligned = (start + kHugePage - 1) & ~(std::uintptr_t{kHugePage} - 1);
  if (aligned > start) munmap(raw, aligned - start);
  if (const std::size_t tail = padded - (aligned - start) - size) munmap(reinterpret_cast<void*>(aligned + size), tail);
  return reinterpret_cast<void*>(aligned);
}
#endif

}  // namespace

void* allocate_big(std::size_t bytes) {
#ifdef __linux__
  if (bytes >= kBigBlock) {
    if (void* p = map_aligned(mapped_size(bytes))) return p;
    throw std::bad_alloc();
  }
#endif
  return ::operator new(bytes ? bytes : 1);
}

void release_big(void* p, std::size_t bytes) noexcept {
#ifdef __linux__
  if (bytes >= kBigBlock) {
    munmap(p, mapped_size(bytes));
    return;
  }
#endif
  ::operator delete(p);
}

void release_pages(void* p, std::size_t bytes) noexcept {
#ifdef __linux__
  const long page = sysconf(_SC_PAGESIZE);
  const std::uintptr_t small = page > 0 ? static_cast<std::uintptr_t>(page) : 4096;
  const auto at = reinterpret_cast<std::uintptr_t>(p);
  const std::uintptr_t from = (at + small - 1) & ~(small - 1), to = (at + bytes) & ~(small - 1);
  if (to > from) madvise(reinterpret_cast<void*>(from), to - from, MADV_DONTNEED);
#else
  (void)p, (void)bytes;
#endif
}

void prefer_small_pages(const void* p, std::size_t bytes) noexcept {
#ifdef __linux__
  const auto at = reinterpret_cast<std::uintptr_t>(p);
  const std::uintptr_t from = at & ~(std::uintptr_t{4095}), to = (at + bytes + 4095) & ~(std::uintptr_t{4095});
  if (to > from) madvise(reinterpret_cast<void*>(from), to - from, MADV_NOHUGEPAGE);
#else
  (void)p, (void)bytes;
#endif
}

void release_free_heap() noexcept {
#ifdef __GLIBC__
  malloc_trim(0);
#endif
}

}  // namespace deltri
