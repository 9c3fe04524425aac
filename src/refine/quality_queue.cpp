#include "refine/quality_queue.h"

#include <algorithm>
#include <bit>
#include <cmath>

namespace deltri {

namespace {

// floor(log2(x)) for a finite x >= 1, from its exponent bits.
unsigned floor_log2(double x) { return static_cast<unsigned>((std::bit_cast<std::uint64_t>(x) >> 52) - 1023); }

}  // namespace

unsigned paper_bucket(double q) {
  if (!(q >= 1.0)) return q > 0.0 ? 1u : 0u;  // size-only (0) or a ratio at the bound
  if (!std::isfinite(q)) return QualityQueue::kBuckets - 1;
  const std::uint64_t half = (std::bit_cast<std::uint64_t>(q) >> 51) & 1u;  // first mantissa bit: m >= 1.5
  const std::uint64_t step = 2 * std::uint64_t{floor_log2(q)} + half;
  return static_cast<unsigned>(std::min<std::uint64_t>(1 + step, QualityQueue::kBuckets - 1));
}

unsigned edge_bucket(double shortest2, double reference2, unsigned last) {
  const double ratio = reference2 / shortest2;
  if (!std::isfinite(ratio)) return last;
  if (!(ratio >= 1.0)) return 1;
  return std::min(1 + floor_log2(ratio), last);
}

unsigned ratio_bucket(const Badness& b, double reference2) {
  if (!b.skinny) return 0;
  const double q = b.ratio2_over_bound2;
  if (!(q >= kSkinnyRatio2)) return edge_bucket(b.shortest2, reference2, kFirstSkinnyBucket - 1);
  if (!std::isfinite(q)) return QualityQueue::kBuckets - 1;
  return std::min(kFirstSkinnyBucket + floor_log2(q / kSkinnyRatio2), QualityQueue::kBuckets - 1);
}

void QualityQueue::push(const QueuedTriangle& entry, const Badness& why) {
  switch (order_) {
    case QueueOrder::Ratio:
      return push_to_bucket(entry, ratio_bucket(why, reference2_));
    case QueueOrder::Paper:
      return push_to_bucket(entry, why.skinny ? paper_bucket(why.ratio2_over_bound2) : 0u);
    case QueueOrder::Edge:
      return push_to_bucket(entry, why.skinny ? edge_bucket(why.shortest2, reference2_) : 0u);
    case QueueOrder::Fifo:
      return push_to_bucket(entry, 0u);
    case QueueOrder::RatioHeap: {
      // The tiers of ratio_bucket, each ordered exactly.
      if (!why.skinny) return push_keyed(entry, 0, 0.0);
      if (why.ratio2_over_bound2 >= kSkinnyRatio2) return push_keyed(entry, 2, why.ratio2_over_bound2);
      return push_keyed(entry, 1, reference2_ / why.shortest2);
    }
    case QueueOrder::PaperHeap:
      return push_keyed(entry, why.skinny ? 1 : 0, why.skinny ? why.ratio2_over_bound2 : 0.0);
  }
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

void QualityQueue::push_to_bucket(const QueuedTriangle& entry, unsigned bucket) {
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

void QualityQueue::push_keyed(const QueuedTriangle& entry, unsigned tier, double key) {
  heap_.push_back({tier, key, next_age_--, entry});
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
