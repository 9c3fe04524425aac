#include "refine/quality_queue.h"

#include <algorithm>
#include <bit>
#include <cmath>

namespace deltri {

unsigned quality_bucket(double q) {
  if (!(q >= 1.0)) return q > 0.0 ? 1u : 0u;  // size-only (0) or a ratio at the bound
  if (!std::isfinite(q)) return QualityQueue::kBuckets - 1;
  const std::uint64_t bits = std::bit_cast<std::uint64_t>(q);
  const std::uint64_t exponent = (bits >> 52) - 1023;  // q >= 1, so this is log2 floor
  const std::uint64_t half = (bits >> 51) & 1u;        // first mantissa bit: m >= 1.5
  const std::uint64_t step = 2 * exponent + half;
  return static_cast<unsigned>(std::min<std::uint64_t>(1 + step, QualityQueue::kBuckets - 1));
}

unsigned edge_bucket(double shortest2, double reference2) {
  const double ratio = reference2 / shortest2;
  if (!std::isfinite(ratio)) return QualityQueue::kBuckets - 1;
  if (!(ratio >= 1.0)) return 1;
  int exponent = 0;
  std::frexp(ratio, &exponent);  // ratio = m 2^exponent, 0.5 <= m < 1
  const int bucket = std::clamp(exponent, 1, static_cast<int>(QualityQueue::kBuckets) - 1);
  return static_cast<unsigned>(bucket);
}

void QualityQueue::note_push() {
  if (++size_ > peak_) peak_ = size_;
}

void QualityQueue::push(const QueuedTriangle& entry, unsigned bucket) {
  buckets_[bucket].items.push_back(entry);
  nonempty_ |= std::uint64_t{1} << bucket;
  note_push();
}

void QualityQueue::push_keyed(const QueuedTriangle& entry, double key) {
  heap_.push_back({key, next_age_--, entry});
  std::push_heap(heap_.begin(), heap_.end());
  note_push();
}

const QueuedTriangle* QualityQueue::peek(std::size_t ahead) const {
  if (!heap_.empty() || nonempty_ == 0) return nullptr;
  const Fifo& fifo = buckets_[63u - static_cast<unsigned>(std::countl_zero(nonempty_))];
  const std::size_t at = fifo.head + ahead;
  return at < fifo.items.size() ? &fifo.items[at] : nullptr;
}

std::optional<QueuedTriangle> QualityQueue::pop() {
  if (!heap_.empty()) {
    std::pop_heap(heap_.begin(), heap_.end());
    const QueuedTriangle entry = heap_.back().entry;
    heap_.pop_back();
    --size_;
    return entry;
  }
  if (nonempty_ == 0) return std::nullopt;
  const unsigned bucket = 63u - static_cast<unsigned>(std::countl_zero(nonempty_));
  Fifo& fifo = buckets_[bucket];
  const QueuedTriangle entry = fifo.items[fifo.head++];
  --size_;
  if (fifo.head == fifo.items.size()) {
    fifo.items.clear();
    fifo.head = 0;
    nonempty_ &= ~(std::uint64_t{1} << bucket);
  } else if (fifo.head >= 4096 && 2 * fifo.head >= fifo.items.size()) {
    // Reclaim the consumed front so a long-lived bucket does not grow without bound.
    fifo.items.erase(fifo.items.begin(), fifo.items.begin() + static_cast<std::ptrdiff_t>(fifo.head));
    fifo.head = 0;
  }
  return entry;
}

}  // namespace deltri
