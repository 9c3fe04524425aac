#include "refine/quality_queue.h"

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

void QualityQueue::push(const QueuedTriangle& entry, unsigned bucket) {
  buckets_[bucket].items.push_back(entry);
  nonempty_ |= std::uint64_t{1} << bucket;
  if (++size_ > peak_) peak_ = size_;
}

std::optional<QueuedTriangle> QualityQueue::pop() {
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
