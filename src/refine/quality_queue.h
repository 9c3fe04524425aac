// The queue of bad triangles: 64 FIFO buckets, the most urgent non-empty one served first.
//
// What "urgent" means is a choice (QueueOrder), measured on the corpus in docs/refinement.md:
// - RatioBuckets, Shewchuk 2001, section 7: keyed by the circumradius-to-shortest-edge ratio,
//   worst first. With circumcentres it beats FIFO order by a third, as the paper says; with
//   off-centres it grades poorly (each very skinny triangle grows a chain of off-centres away
//   from its short edge before the small features near it are resolved) and gives 24% (-q30) to
//   85% (-q33) more triangles than Triangle 1.6 on the corpus.
// - EdgeBuckets, the default: keyed by the length of the shortest edge, shortest first, the
//   order Triangle 1.6 adopted together with off-centres. Refinement then spreads outwards from
//   the smallest features like a front, and a large skinny triangle is often gone (split by the
//   refinement of its small neighbours) before its turn comes.
// - SingleFifo and RatioHeap (an exact max-heap of the ratio) exist to measure the others.
//
// Bucket 0 holds triangles that are well shaped but too large (area or size test). A triangle
// whose ratio r exceeds the bound B is keyed by q = r^2 / B^2 >= 1: writing q = m 2^k with
// 1 <= m < 2, it goes to bucket 1 + 2k + (m >= 1.5), clamped to 63. Two buckets per octave of q
// (boundaries at 2^k and 1.5 2^k, a factor of about 1.19 in r per bucket on average) make buckets
// 1..62 cover r from B to B 2^15.5 (about 46,000 B); bucket 63 collects everything skinnier. The
// index is the exponent and first mantissa bit of q, read from its bits; no logarithm is computed.
//
// A 64-bit mask has a bit set for every non-empty bucket; the worst non-empty bucket is its highest
// set bit, one instruction. Entries remember the triangle's three vertices: a popped entry whose
// slot no longer holds those vertices (the triangle was split or flipped away) is stale and dropped.
//
// Each bucket is a chain of fixed-size blocks taken from one pool and given back when emptied, so
// the queue holds about its live entries (plus one partial block per bucket at each end) instead
// of the doubled capacities and consumed fronts of 64 growing arrays: on the 45x45-hole workload
// at -q30, 25.7 MB of vectors for a peak of 453,518 entries (7.3 MB).
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "mesh/ids.h"

namespace deltri {

struct QueuedTriangle {
  TriangleId triangle;
  VertexId a, b, c;  // the corners when queued
};

enum class QueueOrder { EdgeBuckets, RatioBuckets, SingleFifo, RatioHeap };

// The ratio bucket for a bad triangle: ratio_squared_over_bound_squared = (r/B)^2, or 0 for a
// triangle that is bad only for its size.
unsigned quality_bucket(double ratio_squared_over_bound_squared);

// The edge bucket for a skinny triangle whose shortest edge has squared length `shortest2`, in a
// domain of squared diameter `reference2`: 1 + floor(log2(reference2 / shortest2)), clamped to
// 1..63, so each bucket spans a factor of sqrt(2) in length and shorter edges rank higher. Edges
// below reference / 2^31 share bucket 63.
unsigned edge_bucket(double shortest2, double reference2);

class QualityQueue {
 public:
  static constexpr unsigned kBuckets = 64;

  void push(const QueuedTriangle& entry, unsigned bucket);
  // RatioHeap only: entries come out largest key first, oldest first among equal keys.
  void push_keyed(const QueuedTriangle& entry, double key);
  // The oldest entry of the worst non-empty bucket (or the heap's top), or nothing when empty.
  std::optional<QueuedTriangle> pop();
  // The entry `ahead` places behind the next one in the bucket pop() serves now, or null; a hint
  // for prefetching only (a later push may still overtake it).
  const QueuedTriangle* peek(std::size_t ahead) const;
  bool empty() const { return size_ == 0; }
  std::size_t size() const { return size_; }
  std::size_t peak_size() const { return peak_; }
  std::uint64_t nonempty_mask() const { return nonempty_; }

 private:
  static constexpr std::uint32_t kBlock = 1024;  // entries per block (16 KiB)
  static constexpr std::uint32_t kNoBlock = ~std::uint32_t{0};
  struct Block {
    std::array<QueuedTriangle, kBlock> items;
    std::uint32_t next = kNoBlock;
  };
  // A FIFO of blocks: entries [head, ...) of block `first` up to [..., tail) of block `last`.
  struct Fifo {
    std::uint32_t first = kNoBlock, last = kNoBlock;
    std::uint32_t head = 0, tail = 0;
  };
  std::uint32_t take_block();
  void give_back(std::uint32_t block);
  struct Keyed {
    double key;
    std::uint64_t age;  // decreasing, so among equal keys the oldest is the largest
    QueuedTriangle entry;
    bool operator<(const Keyed& o) const { return key < o.key || (key == o.key && age < o.age); }
  };
  void note_push();
  std::array<Fifo, kBuckets> buckets_;
  std::vector<std::unique_ptr<Block>> blocks_;
  std::vector<std::uint32_t> free_blocks_;
  std::vector<Keyed> heap_;
  std::uint64_t next_age_ = ~std::uint64_t{0};
  std::uint64_t nonempty_ = 0;
  std::size_t size_ = 0;
  std::size_t peak_ = 0;
};

}  // namespace deltri
