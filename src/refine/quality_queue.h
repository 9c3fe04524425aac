// The queue of bad triangles: 64 FIFO buckets, the most urgent non-empty one served first
// (Shewchuk 2001, Sec. 7 of Appendix A). A 64-bit mask has a bit set for every non-empty bucket;
// the most urgent is its highest set bit, one instruction. Entries remember the triangle's three
// vertices: a popped entry whose slot no longer holds them (the triangle was split or flipped
// away) is stale and dropped. Bucket 0 holds triangles that are well shaped but too large (area
// or size test): ordering those does not pay (Sec. 7).
//
// The key (QueueOrder; measured on the corpus in docs/refinement.md):
// - Ratio, the default: the circumradius-to-shortest-edge ratio r against the bound
//   B = 1 / (2 sin theta), in two tiers. Skinny triangles, r >= 4B, take buckets 48..63, one per
//   factor sqrt(2) in r, worst first, as the paper has it. Mildly skinny ones, B < r < 4B, take
//   buckets 1..47 by the length l of their shortest edge against the diameter D of the domain,
//   one bucket per factor sqrt(2) in l, shortest first. With off-centres the paper's order over the
//   whole range refines 1.4 times as much as Triangle 1.6 at -q33: mildly skinny triangles are
//   split large ones first, each split a little finer than the last when B < 1 (theta > 30), and
//   the cascades spread through the domain; served smallest first they settle where they start.
// - Paper: the ratio over the whole range, as Sec. 7 describes it (buckets 1..63, two per octave
//   of (r/B)^2, worst first).
// - Edge: the shortest edge over the whole range (Triangle 1.6's key).
// - Fifo: one bucket for everything. RatioHeap and PaperHeap: exact max-heaps of the Ratio and
//   Paper keys (oldest first among equal keys), what their buckets approximate.
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

enum class QueueOrder { Ratio, Paper, Edge, Fifo, RatioHeap, PaperHeap };

// Why a triangle is queued, as refinement measured it.
struct Badness {
  bool skinny = false;              // its ratio is above the bound (else it is only too large)
  double ratio2_over_bound2 = 0.0;  // (r / B)^2, > 1 when skinny
  double shortest2 = 0.0;           // squared length of its shortest edge
};

// Ratio: (r/B)^2 >= kSkinnyRatio2 (r >= 4B, an angle under 7.2 degrees at -q30) is skinny.
inline constexpr double kSkinnyRatio2 = 16.0;
inline constexpr unsigned kFirstSkinnyBucket = 48;

// The Ratio bucket: 0 size only; 1 + floor(log2(D^2 / l^2)) clamped to 1..47 for the mildly
// skinny (edges below D / 2^23 share bucket 47); 48 + floor(log2(q / 16)) clamped to 48..63 for the
// skinny (ratios beyond 4B 2^7.5, about 724 B, share bucket 63). reference2 is D^2.
unsigned ratio_bucket(const Badness& b, double reference2);

// The Paper bucket of q = (r/B)^2, or 0 for a triangle that is bad only for its size: writing
// q = m 2^k with 1 <= m < 2, bucket 1 + 2k + (m >= 1.5), clamped to 63. Two buckets per octave of
// q (a factor of about 1.19 in r per bucket) make buckets 1..62 cover r from B to B 2^15.5 (about
// 46,000 B); bucket 63 collects everything skinnier. Read from q's exponent and first mantissa
// bit; no logarithm is computed.
unsigned paper_bucket(double ratio_squared_over_bound_squared);

// The Edge bucket for a skinny triangle whose shortest edge has squared length `shortest2`, in a
// domain of squared diameter `reference2`: 1 + floor(log2(reference2 / shortest2)), clamped to
// 1..`last`, so each bucket spans a factor of sqrt(2) in length and shorter edges rank higher.
unsigned edge_bucket(double shortest2, double reference2, unsigned last = 63);

class QualityQueue {
 public:
  static constexpr unsigned kBuckets = 64;

  // reference2: the squared diameter of the domain, the scale of the edge keys.
  explicit QualityQueue(QueueOrder order = QueueOrder::Ratio, double reference2 = 1.0)
      : order_(order), reference2_(reference2) {}

  // Queues a bad triangle where the order puts it.
  void push(const QueuedTriangle& entry, const Badness& why);
  // The two disciplines underneath: a FIFO bucket, and the heap (largest tier, then largest key,
  // then oldest first).
  void push_to_bucket(const QueuedTriangle& entry, unsigned bucket);
  void push_keyed(const QueuedTriangle& entry, unsigned tier, double key);
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
    unsigned tier;
    double key;
    std::uint64_t age;  // decreasing, so among equal keys the oldest is the largest
    QueuedTriangle entry;
    bool operator<(const Keyed& o) const {
      if (tier != o.tier) return tier < o.tier;
      return key < o.key || (key == o.key && age < o.age);
    }
  };
  void note_push();
  QueueOrder order_;
  double reference2_;
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
