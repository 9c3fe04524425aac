// The queue of bad triangles: 64 FIFO buckets keyed by the circumradius-to-shortest-edge ratio,
// worst served first (Shewchuk 2001, section 7: splitting the worst triangles first gives fewer
// and better-graded triangles than FIFO order).
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
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "mesh/ids.h"

namespace deltri {

struct QueuedTriangle {
  TriangleId triangle;
  VertexId a, b, c;  // the corners when queued
};

// The bucket for a bad triangle: ratio_squared_over_bound_squared = (r/B)^2, or 0 for a triangle
// that is bad only for its size.
unsigned quality_bucket(double ratio_squared_over_bound_squared);

class QualityQueue {
 public:
  static constexpr unsigned kBuckets = 64;

  void push(const QueuedTriangle& entry, unsigned bucket);
  // The oldest entry of the worst non-empty bucket, or nothing when the queue is empty.
  std::optional<QueuedTriangle> pop();
  bool empty() const { return nonempty_ == 0; }
  std::size_t size() const { return size_; }
  std::size_t peak_size() const { return peak_; }
  std::uint64_t nonempty_mask() const { return nonempty_; }

 private:
  struct Fifo {
    std::vector<QueuedTriangle> items;
    std::size_t head = 0;
  };
  std::array<Fifo, kBuckets> buckets_;
  std::uint64_t nonempty_ = 0;
  std::size_t size_ = 0;
  std::size_t peak_ = 0;
};

}  // namespace deltri
