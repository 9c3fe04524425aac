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

std::uint32_t QualityQueue::take_block() {
  if (!free_blocks_.empty()) {
    const std::uint32_t block = free_blocks_.back();
    free_blocks_.pop_back();
    blocks_[block]->next = kNoBlock;
    return block;
  }
  blocks_.push_back(std::make_unique<Block>());
  return static_cast<std::uint32_t>(blocks_.size() - 1);
}

void QualityQueue::give_back(std::uint32_t block) { free_blocks_.push_back(block); }

void QualityQueue::push(const QueuedTriangle& entry, unsigned bucket) {
  Fifo& fifo = buckets_[bucket];
  if (fifo.last == kNoBlock) {
    fifo.first = fifo.last = take_block();
    fifo.head = fifo.tail = 0;
  } else if (fifo.tail == kBlock) {
    const std::uint32_t block = take_block();
    blocks_[fifo.last]->next = block;
    fifo.last = block;
    fifo.tail = 0;
  }
  blocks_[fifo.last]->items[fifo.tail++] = entry;
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
  std::uint32_t block = fifo.first;
  std::size_t at = fifo.head + ahead;
  while (at >= kBlock && block != fifo.last) {
    block = blocks_[block]->next;
    at -= kBlock;
  }
  if (block == fifo.last && at >= fifo.tail) return nullptr;
  return at < kBlock ? &blocks_[block]->items[at] : nullptr;
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
  const QueuedTriangle entry = blocks_[fifo.first]->items[fifo.head++];
  --size_;
  if (fifo.first == fifo.last && fifo.head == fifo.tail) {  // the bucket is empty
    give_back(fifo.first);
    fifo = Fifo{};
    nonempty_ &= ~(std::uint64_t{1} << bucket);
  } else if (fifo.head == kBlock) {  // the front block is used up
    const std::uint32_t used = fifo.first;
    fifo.first = blocks_[used]->next;
    fifo.head = 0;
    give_back(used);
  }
  return entry;
}

}  // namespace deltri
