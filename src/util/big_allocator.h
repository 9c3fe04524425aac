// Storage for the few arrays that grow with the input (coordinates, triangle corners and links,
// sort buffers, file text). Blocks of at least kBigBlock bytes are mapped on their own and aligned
// to 2 MiB (so that PageWarmer's ranges are whole huge pages where the system makes them anyway,
// THP "always"). They are not advised into transparent huge pages: on the project's machine (a
// virtual machine that hands free 8 MiB blocks back to its host) a fresh huge page is memory the
// host must fault in again, and run after run, interleaved with other programs, small pages were
// as fast or faster on every benchmark and far steadier (1M points 0.34 against 0.39 s, the 5M
// square 1.32 against 1.40 s: docs/benchmarks.md, "Huge pages and the host").
#pragma once

#include <cstddef>
#include <new>
#include <vector>

namespace deltri {

// Smaller blocks go to operator new: a huge page would be mostly empty.
inline constexpr std::size_t kBigBlock = std::size_t{4} << 20;

// Throws std::bad_alloc. `bytes` must be passed unchanged to release_big.
void* allocate_big(std::size_t bytes);
void release_big(void* p, std::size_t bytes) noexcept;

// Gives the whole pages inside [p, p + bytes) back to the system, for memory that will not be read
// again before it is freed (a block being copied elsewhere piece by piece); nothing elsewhere.
void release_pages(void* p, std::size_t bytes) noexcept;

// Asks that the pages of [p, p + bytes) not yet touched be small ones (refine/refine_in_parts.cpp: two
// meshes growing at once, whose last, partly used huge pages would add to the peak).
void prefer_small_pages(const void* p, std::size_t bytes) noexcept;

// Gives the free memory that the C library's allocator holds back to the system, where it can
// (glibc's malloc_trim; nothing elsewhere).
void release_free_heap() noexcept;

template <class T>
struct BigAllocator {
  using value_type = T;
  BigAllocator() = default;
  template <class U>
  BigAllocator(const BigAllocator<U>&) noexcept {}  // NOLINT: allocators convert implicitly
  T* allocate(std::size_t n) {
    if (n > static_cast<std::size_t>(-1) / sizeof(T)) throw std::bad_array_new_length();
    return static_cast<T*>(allocate_big(n * sizeof(T)));
  }
  void deallocate(T* p, std::size_t n) noexcept { release_big(p, n * sizeof(T)); }
  template <class U>
  bool operator==(const BigAllocator<U>&) const noexcept { return true; }
};

template <class T>
using BigVector = std::vector<T, BigAllocator<T>>;

// An uninitialised byte buffer from the same source, for file text.
class BigBytes {
 public:
  BigBytes() = default;
  explicit BigBytes(std::size_t size) : data_(static_cast<char*>(allocate_big(size))), size_(size) {}
  BigBytes(BigBytes&& other) noexcept : data_(other.data_), size_(other.size_) { other.data_ = nullptr, other.size_ = 0; }
  BigBytes& operator=(BigBytes&& other) noexcept {
    if (this != &other) {
      reset();
      data_ = other.data_, size_ = other.size_;
      other.data_ = nullptr, other.size_ = 0;
    }
    return *this;
  }
  ~BigBytes() { reset(); }
  char* get() const { return data_; }
  std::size_t capacity() const { return size_; }

 private:
  void reset() noexcept {
    if (data_) release_big(data_, size_);
    data_ = nullptr, size_ = 0;
  }
  char* data_ = nullptr;
  std::size_t size_ = 0;
};

// Appends f(x) for every x of `from` from index `first` on to `to` and frees `from`, giving its
// pages back as they are copied, so that the two arrays never hold their whole size at once (that
// set the peak memory of refine/refine_in_parts.cpp's join). `to` grows a block at a time from a buffer on
// this thread's stack, not an element at a time: its size, rewritten at every element, sits in
// the mesh beside the arrays that another thread appends to at once (mesh/parts.cpp).
template <class T, class U, class F>
void move_appending(BigVector<T>& from, BigVector<U>& to, F f, std::size_t first = 0) {
  constexpr std::size_t kChunk = std::size_t{1} << 16;
  constexpr std::size_t kBlock = 256;
  U block[kBlock];
  for (std::size_t i = first; i < from.size(); i += kChunk) {
    const std::size_t end = from.size() < i + kChunk ? from.size() : i + kChunk;
    for (std::size_t k = i; k < end; k += kBlock) {
      const std::size_t n = end - k < kBlock ? end - k : kBlock;
      for (std::size_t j = 0; j < n; ++j) block[j] = f(from[k + j]);
      to.insert(to.end(), block, block + n);
    }
    release_pages(from.data() + i, (end - i) * sizeof(T));
  }
  BigVector<T>().swap(from);
}

}  // namespace deltri
