#include "refine/quality_queue.h"

#include <algorithm>
#include <bit>
#include <cmath>

#include "util/big_allocator.h"

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

unsigned edge_bucket(double shortest2, double reference2) {
  const double ratio = reference2 / shortest2;
  if (!std::isfinite(ratio)) return QualityQueue::kBuckets - 1;
  if (!(ratio >= 1.0)) return 1;
  return std::min(1 + floor_log2(ratio), QualityQueue::kBuckets - 1);
}

unsigned edge_level(double shortest2, double reference2, unsigned bits) {
  const double x = reference2 / shortest2;
  if (!std::isfinite(x)) return kTopLevel;
  if (!(x >= 1.0)) return 0;
  const unsigned fraction = static_cast<unsigned>((std::bit_cast<std::uint64_t>(x) >> (52 - bits)) & ((1u << bits) - 1));
  return std::min((floor_log2(x) << bits) + fraction, kTopLevel);
}

unsigned edge_level_bits(double theta_deg) { return theta_deg > 30.0 ? kFineLevelBits : kCoarseLevelBits; }

unsigned QualityQueue::window_bucket(unsigned level) const {
  const int above = static_cast<int>(level) - window_base_;
  if (above <= 0) return 1;
  return std::min(1 + static_cast<unsigned>(above), kWindowBuckets);
}

void QualityQueue::push(const QueuedTriangle& entry, const Badness& why) {
  switch (order_) {
    case QueueOrder::ShortestEdge: {
      if (!why.skinny) return push_to_bucket(entry, 0);
      const unsigned level = edge_level(why.shortest2, reference2_, level_bits_);
      if (static_cast<int>(level) > window_base_ + static_cast<int>(kWindowBuckets - 1)) raise_window(level);
      append_leveled(entry, level, window_bucket(level));
      return note_push();
    }
    case QueueOrder::Paper:
      return push_to_bucket(entry, why.skinny ? paper_bucket(why.ratio2_over_bound2) : 0u);
    case QueueOrder::Edge:
      return push_to_bucket(entry, why.skinny ? edge_bucket(why.shortest2, reference2_) : 0u);
    case QueueOrder::Fifo:
      return push_to_bucket(entry, 0u);
    case QueueOrder::ShortestEdgeHeap: {
      // The ShortestEdge order's key, exactly.
      if (!why.skinny) return push_keyed(entry, 0, 0.0);
      return push_keyed(entry, 1, reference2_ / why.shortest2);
    }
    case QueueOrder::PaperHeap:
      return push_keyed(entry, why.skinny ? 1 : 0, why.skinny ? why.ratio2_over_bound2 : 0.0);
  }
}

template <class Visit, class Done>
void QualityQueue::for_each_entry(const Fifo& fifo, Visit&& visit, Done&& done) {
  for (std::uint32_t block = fifo.first; block != kNoBlock;) {
    const std::uint32_t from = block == fifo.first ? fifo.head : 0;
    const std::uint32_t to = block == fifo.last ? fifo.tail : capacity(block);
    for (std::uint32_t i = from; i < to; ++i) visit(blocks_[block][i], block, i);
    const std::uint32_t next = block == fifo.last ? kNoBlock : next_[block];
    done(block);
    block = next;
  }
}

// Raises the window so that `level` lies kWindowHeadroom levels below its top. The buckets that
// stay in the window move down as a whole (their levels are one each); the ones that fall to or
// below the new base join bucket 1 entry by entry, in FIFO order, their blocks given back as
// they go.
// Called only for a level above the window's top, so the window moves up by more than
// kWindowHeadroom levels.
void QualityQueue::raise_window(unsigned level) {
  const int base = static_cast<int>(level + kWindowHeadroom) - static_cast<int>(kWindowBuckets - 1);
  const int shift = base - window_base_;
  const unsigned last = kWindowBuckets;
  const unsigned merged = static_cast<unsigned>(std::min<int>(shift + 1, static_cast<int>(last)));
  for (unsigned b = 2; b <= merged; ++b) {
    const Fifo old = buckets_[b];
    buckets_[b] = Fifo{};
    const unsigned level = static_cast<unsigned>(window_base_) + b - 1;  // bucket b's
    for_each_entry(old, [&](const QueuedTriangle& e, std::uint32_t, std::uint32_t) { append_leveled(e, level, 1); },
                   [&](std::uint32_t block) { give_back(block); });
  }
  for (unsigned b = merged + 1; b <= last; ++b) {
    buckets_[b - static_cast<unsigned>(shift)] = buckets_[b];
    buckets_[b] = Fifo{};
  }
  window_base_ = base;
  for (unsigned b = 2; b <= last; ++b) {
    const std::uint64_t bit = std::uint64_t{1} << b;
    nonempty_ = buckets_[b].first != kNoBlock ? nonempty_ | bit : nonempty_ & ~bit;
  }
}

// Deals bucket 1 out again over a window whose top lies kWindowHeadroom levels above its highest
// level, in two passes (the highest level, then the moves). Each block of the old chain is given
// back as soon as its entries have moved, so the new chains can reuse it.
void QualityQueue::move_window() {
  const Fifo old = buckets_[1];
  unsigned highest = 0;
  for_each_entry(old, [&](const QueuedTriangle&, std::uint32_t block, std::uint32_t i) {
    highest = std::max<unsigned>(highest, level_at(block, i));
  }, [](std::uint32_t) {});
  window_base_ = static_cast<int>(highest + kWindowHeadroom) - static_cast<int>(kWindowBuckets - 1);
  buckets_[1] = Fifo{};
  nonempty_ &= ~(std::uint64_t{1} << 1);
  for_each_entry(old, [&](const QueuedTriangle& e, std::uint32_t block, std::uint32_t i) {
    const unsigned level = level_at(block, i);
    append_leveled(e, level, window_bucket(level));
  }, [&](std::uint32_t block) { give_back(block); });
}

void QualityQueue::note_push() {
  if (++size_ > peak_) peak_ = size_;
}

// Spare blocks whose pages are still there first; a released one faults its pages in again.
std::uint32_t QualityQueue::take_block() {
  for (std::vector<std::uint32_t>* spares : {&free_blocks_, &released_blocks_}) {
    if (spares->empty()) continue;
    const std::uint32_t block = spares->back();
    spares->pop_back();
    next_[block] = kNoBlock;
    return block;
  }
  const auto block = static_cast<std::uint32_t>(blocks_.size());
  blocks_.push_back(std::make_unique_for_overwrite<QueuedTriangle[]>(capacity(block)));  // written before read: no clear
  next_.push_back(kNoBlock);
  levels_.emplace_back();
  return static_cast<std::uint32_t>(blocks_.size() - 1);
}

// Beyond kSpareBlocks, a block given back returns its pages to the system: the queue then holds
// about its live entries rather than the most it ever held. It peaks halfway through refinement,
// the mesh at the end, and the pool at its peak size had set the peak memory there. A queue that
// never grew past kResidentBlocks keeps its pages, and a small block holds no whole page.
void QualityQueue::give_back(std::uint32_t block) {
  if (free_blocks_.size() < kSpareBlocks || blocks_.size() <= kResidentBlocks || capacity(block) < kBlock) {
    free_blocks_.push_back(block);
    return;
  }
  release_pages(blocks_[block].get(), kBlock * sizeof(QueuedTriangle));
  levels_[block].reset();
  released_blocks_.push_back(block);
}

void QualityQueue::append_leveled(const QueuedTriangle& entry, unsigned level, unsigned bucket) {
  append(entry, bucket);
  if (bucket != 1) return;  // buckets 2..63 imply the level
  const Fifo& fifo = buckets_[1];
  std::unique_ptr<std::uint16_t[]>& levels = levels_[fifo.last];
  if (!levels) levels = std::make_unique_for_overwrite<std::uint16_t[]>(capacity(fifo.last));
  levels[fifo.tail - 1] = static_cast<std::uint16_t>(level);
}

void QualityQueue::append(const QueuedTriangle& entry, unsigned bucket) {
  Fifo& fifo = buckets_[bucket];
  if (fifo.last == kNoBlock) {
    fifo.first = fifo.last = take_block();
    fifo.head = fifo.tail = 0;
  } else if (fifo.tail == capacity(fifo.last)) {
    const std::uint32_t block = take_block();
    next_[fifo.last] = block;
    fifo.last = block;
    fifo.tail = 0;
  }
  blocks_[fifo.last][fifo.tail++] = entry;
  nonempty_ |= std::uint64_t{1} << bucket;
}

void QualityQueue::push_to_bucket(const QueuedTriangle& entry, unsigned bucket) {
  append(entry, bucket);
  note_push();
}

void QualityQueue::push_keyed(const QueuedTriangle& entry, unsigned tier, double key) {
  heap_.push_back({tier, key, next_age_--, entry});
  std::push_heap(heap_.begin(), heap_.end());
  note_push();
}

const QueuedTriangle* QualityQueue::peek(std::size_t ahead) const {
  if (!heap_.empty() || nonempty_ == 0) return nullptr;
  const Fifo& fifo = buckets_[top_bucket()];
  std::uint32_t block = fifo.first;
  std::size_t at = fifo.head + ahead;
  while (at >= capacity(block) && block != fifo.last) {
    at -= capacity(block);
    block = next_[block];
  }
  if (block == fifo.last && at >= fifo.tail) return nullptr;
  return at < capacity(block) ? &blocks_[block][at] : nullptr;
}

QueuedTriangle QualityQueue::take_front(unsigned bucket) {
  Fifo& fifo = buckets_[bucket];
  const QueuedTriangle entry = blocks_[fifo.first][fifo.head++];
  if (fifo.first == fifo.last && fifo.head == fifo.tail) {  // the bucket is empty
    give_back(fifo.first);
    fifo = Fifo{};
    nonempty_ &= ~(std::uint64_t{1} << bucket);
  } else if (fifo.head == capacity(fifo.first)) {  // the front block is used up
    const std::uint32_t used = fifo.first;
    fifo.first = next_[used];
    fifo.head = 0;
    give_back(used);
  }
  return entry;
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
  if (top_bucket() == 1 && order_ == QueueOrder::ShortestEdge) move_window();
  const unsigned bucket = top_bucket();
  --size_;
  return take_front(bucket);
}

}  // namespace deltri
