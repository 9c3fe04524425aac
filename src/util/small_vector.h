// A list whose first N items live in the object itself, for the short lists of hot loops (a flip
// stack, a probe's encroached subsegments): the common case allocates nothing, and a longer list
// moves to the heap once and stays there.
#pragma once

#include <cstddef>
#include <vector>

namespace deltri {

template <class T, std::size_t N>
class SmallVector {
 public:
  void push_back(const T& x) {
    if (!spilled_ && size_ < N) {
      in_place_[size_++] = x;
      return;
    }
    if (!spilled_) {
      heap_.assign(in_place_, in_place_ + N);
      spilled_ = true;
    }
    heap_.push_back(x);
    ++size_;
  }
  void pop_back() {
    if (spilled_) heap_.pop_back();
    --size_;
  }
  const T& back() const { return data()[size_ - 1]; }
  bool empty() const { return size_ == 0; }
  std::size_t size() const { return size_; }
  const T& operator[](std::size_t i) const { return data()[i]; }
  const T* begin() const { return data(); }
  const T* end() const { return data() + size_; }

 private:
  const T* data() const { return spilled_ ? heap_.data() : in_place_; }

  T in_place_[N];
  std::size_t size_ = 0;
  bool spilled_ = false;
  std::vector<T> heap_;
};

}  // namespace deltri
