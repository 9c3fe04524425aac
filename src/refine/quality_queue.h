// The queue of bad triangles: 64 FIFO buckets, the most urgent non-empty one served first
// (Shewchuk 2001, Sec. 7 of Appendix A). A 64-bit mask has a bit set for every non-empty bucket;
// the most urgent is its highest set bit, one instruction. Entries remember the triangle's three
// vertices: a popped entry whose slot no longer holds them (the triangle was split or flipped
// away) is stale and dropped. Bucket 0 holds triangles that are well shaped but too large (area
// or size test): ordering those does not pay (Sec. 7).
//
// The key (QueueOrder; measured on the corpus in docs/refinement.md):
// - ShortestEdge, the default: every skinny triangle by the length l of its shortest edge,
//   shortest first. Its edge level (edge_level, eight levels per octave of l, 32 above 30
//   degrees) picks a bucket among 1..63 in a window of 62 levels that slides towards longer edges
//   as refinement works its way up (below). Served smallest first, the cascades of splits settle
//   where they start: when B < 1 (theta > 30) each split of a mildly skinny triangle is a little
//   finer than the last, so serving large ones first (the paper's order) spreads cascades through
//   the domain and refines 1.4 times as much as Triangle 1.6 at -q33. The finer the levels the
//   better (one bucket per factor sqrt(2) in l made 2.1 % more triangles at -q33 on the corpus).
//   Slivers are not served first either: their off-centres, 1.6 shortest edges from that edge,
//   would go in before the grading around them and fix points that finer triangles served first
//   place better (a plate with a 1e-4 wide slit at -q30: 564 triangles against 444).
// - Paper: the ratio over the whole range, as Sec. 7 describes it (buckets 1..63, two per octave
//   of (r/B)^2, worst first).
// - Edge: the shortest edge over the whole range, one bucket per factor sqrt(2) (Triangle 1.6's
//   key).
// - Fifo: one bucket for everything. ShortestEdgeHeap and PaperHeap: exact max-heaps of the
//   ShortestEdge and Paper keys (oldest first among equal keys), what their buckets approximate.
//
// The window: bucket 1 holds every level at or below the window's base, and
// buckets 2..63 one level each above it. When bucket 1 is the worst non-empty bucket left, the
// window is moved down so that the highest level in bucket 1 lands kWindowHeadroom levels below
// the top (room for the slightly shorter edges that splitting makes), and bucket 1's entries are
// dealt out again, in their FIFO order. An entry in buckets 2..63 has the level its bucket names
// (the window's base plus the bucket less one), so only bucket 1's entries keep their levels, in
// an array of 16-bit levels beside each block that has served in bucket 1. The first pop places
// the window the same way. A push above the top raises the window instead: the buckets that stay
// inside move as a whole, the ones that fall below join bucket 1. So the order is exact by level
// (FIFO within a level), and each entry moves once per window move that passes it.
//
// Each bucket is a chain of blocks (16 KiB; the first few 1 KiB, for small runs) taken from one
// pool and given back when emptied, so the queue holds about its live entries (plus one partial
// block per bucket at each end) instead of the doubled capacities and consumed fronts of 64
// growing arrays: on the 45x45-hole workload
// at -q30, 25.7 MB of vectors for a peak of 453,518 entries (7.3 MB).
#pragma once

#include <array>
#include <bit>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "mesh/ids.h"

namespace deltri {

// 16 bytes: the ShortestEdge order's edge level is not kept in the entry (the bucket implies it, and
// bucket 1's entries keep theirs beside their block), not 20.
struct QueuedTriangle {
  TriangleId triangle;
  VertexId a, b, c;  // the corners when queued
};
static_assert(sizeof(QueuedTriangle) == 16);

enum class QueueOrder {
  ShortestEdge,
  Paper,
  Edge,
  Fifo,
  ShortestEdgeHeap,
  PaperHeap,
  // The names the switch table (options/switch_table.cpp) still spells; to go when it says ShortestEdge.
  Ratio = ShortestEdge,
  RatioHeap = ShortestEdgeHeap
};

// Why a triangle is queued, as refinement measured it.
struct Badness {
  bool skinny = false;              // its ratio is above the bound (else it is only too large)
  double ratio2_over_bound2 = 0.0;  // (r / B)^2, > 1 when skinny
  double shortest2 = 0.0;           // squared length of its shortest edge
};

inline constexpr unsigned kWindowBuckets = 63;  // buckets 1..63
inline constexpr unsigned kWindowHeadroom = 8;   // levels: one octave of l

// The edge level of a shortest edge with squared length `shortest2` in a domain of squared
// diameter `reference2`: with x = reference2 / shortest2 = m 2^k (1 <= m < 2), 2^bits k plus the
// first `bits` mantissa bits of x. With bits = 2 (m at 1.25, 1.5, 1.75) that is four levels per
// octave of l^2, eight per octave of l; with bits = 4, 32 per octave of l. Higher for shorter
// edges; 0 for x < 1, kTopLevel for a zero-length edge.
inline constexpr unsigned kCoarseLevelBits = 2;
inline constexpr unsigned kFineLevelBits = 4;
inline constexpr unsigned kTopLevel = (1u << kFineLevelBits) * 1024;  // above every level; fits 16 bits
unsigned edge_level(double shortest2, double reference2, unsigned bits = kCoarseLevelBits);

// The mantissa bits of the edge level for an angle bound of theta degrees. Up to 30 degrees
// (B >= 1) eight levels per octave of l; above (B < 1) 32. Above 30 degrees a mildly skinny
// triangle's circumcentre makes edges shorter than its own shortest, so the order among triangles
// whose shortest edges differ by less than 9% still decides how far a cascade spreads: a plate
// with a 1e-4 wide slit at -q33 has 800 triangles with eight levels and 632 with 32 (Triangle
// 1.6: 696), the corpus sum at -q33 falls from 820,883 to 819,323. Up to 30 degrees the finer
// order gains nothing on the corpus (618,141 against 618,929 triangles at -q30) and the 45x45
// holes at -q30 make 2.1% more triangles with it (docs/refinement.md, "The queue").
unsigned edge_level_bits(double theta_deg);

// The Paper bucket of q = (r/B)^2, or 0 for a triangle that is bad only for its size: writing
// q = m 2^k with 1 <= m < 2, bucket 1 + 2k + (m >= 1.5), clamped to 63. Two buckets per octave of
// q (a factor of about 1.19 in r per bucket) make buckets 1..62 cover r from B to B 2^15.5 (about
// 46,000 B); bucket 63 collects everything skinnier. Read from q's exponent and first mantissa
// bit; no logarithm is computed.
unsigned paper_bucket(double ratio_squared_over_bound_squared);

// The Edge bucket for a skinny triangle whose shortest edge has squared length `shortest2`, in a
// domain of squared diameter `reference2`: 1 + floor(log2(reference2 / shortest2)), clamped to
// 1..63, so each bucket spans a factor of sqrt(2) in length and shorter edges rank higher. Edges
// below reference / 2^31 share bucket 63.
unsigned edge_bucket(double shortest2, double reference2);

class QualityQueue {
 public:
  static constexpr unsigned kBuckets = 64;

  // reference2: the squared diameter of the domain, the scale of the edge keys; level_bits: the
  // edge levels' resolution (edge_level_bits) in the ShortestEdge order.
  explicit QualityQueue(QueueOrder order = QueueOrder::ShortestEdge, double reference2 = 1.0,
                        unsigned level_bits = kCoarseLevelBits)
      : order_(order), reference2_(reference2), level_bits_(level_bits) {}

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
  // The first kSmallBlocks blocks hold kSmallBlock entries (1 KiB) each: a small run touches one
  // page per bucket in use with 16 KiB blocks (about 20 page faults), with these about one per 4
  // buckets. They are never released (below a page), and a large run soon takes 16 KiB ones.
  static constexpr std::uint32_t kSmallBlock = 64;
  static constexpr std::size_t kSmallBlocks = 32;
  static constexpr std::uint32_t kNoBlock = ~std::uint32_t{0};
  // A FIFO of blocks: entries [head, ...) of block `first` up to [..., tail) of block `last`.
  struct Fifo {
    std::uint32_t first = kNoBlock, last = kNoBlock;
    std::uint32_t head = 0, tail = 0;
  };
  // Blocks are only ever appended, so a block's number says whether it is one of the small ones.
  static constexpr std::uint32_t capacity(std::uint32_t block) { return block < kSmallBlocks ? kSmallBlock : kBlock; }
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
  // The most urgent non-empty bucket (nonempty_ must not be 0): the mask's highest set bit.
  unsigned top_bucket() const { return 63u - static_cast<unsigned>(std::countl_zero(nonempty_)); }
  void append(const QueuedTriangle& entry, unsigned bucket);  // push_to_bucket, not counted
  // The ShortestEdge order: appends an entry of edge level `level` to `bucket`, keeping the level beside
  // its block when that is bucket 1.
  void append_leveled(const QueuedTriangle& entry, unsigned level, unsigned bucket);
  std::uint16_t level_at(std::uint32_t block, std::uint32_t i) const { return levels_[block][i]; }
  QueuedTriangle take_front(unsigned bucket);                 // the oldest entry of a non-empty bucket
  // The ShortestEdge order's bucket for a skinny triangle of edge level `level` in the current window.
  unsigned window_bucket(unsigned level) const;
  void move_window();
  void raise_window(unsigned level);
  // Calls visit(entry, block, index) for the entries of `fifo` in FIFO order, then done(block) for
  // each of its blocks once its entries have been visited.
  template <class Visit, class Done>
  void for_each_entry(const Fifo& fifo, Visit&& visit, Done&& done);
  QueueOrder order_;
  double reference2_;
  unsigned level_bits_;
  // Levels at or below window_base_ go to bucket 1. Before the first pop the window lies above
  // every level, so everything waits in bucket 1 until move_window() places it.
  int window_base_ = static_cast<int>(kTopLevel) + 1;
  std::array<Fifo, kBuckets> buckets_;
  // By block: its entries, the next block of its chain, its capacity (kSmallBlock or kBlock).
  std::vector<std::unique_ptr<QueuedTriangle[]>> blocks_;
  std::vector<std::uint32_t> next_;
  std::vector<std::unique_ptr<std::uint16_t[]>> levels_;  // by block: null until it serves in bucket 1
  std::vector<std::uint32_t> free_blocks_;      // given back, pages resident
  std::vector<std::uint32_t> released_blocks_;  // given back, pages returned (give_back)
  // Spare blocks kept with their pages: 32 kept up to 0.5 MiB resident per refining part, 0.4 MiB
  // more than 8 (benchmarks.md).
  static constexpr std::size_t kSpareBlocks = 8;
  // A queue of at most this many blocks (0.5 MiB) returns no pages: a small run's madvise calls
  // and the faults that follow them cost more than its whole queue (benchmarks.md, small runs).
  static constexpr std::size_t kResidentBlocks = 32;
  std::vector<Keyed> heap_;
  std::uint64_t next_age_ = ~std::uint64_t{0};
  std::uint64_t nonempty_ = 0;
  std::size_t size_ = 0;
  std::size_t peak_ = 0;
};

}  // namespace deltri
