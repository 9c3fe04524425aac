// Divide and conquer on ghost triangles.
//
// Each sub-triangulation is closed by a ring of ghost triangles, one per convex-hull edge, whose
// third corner is the vertex at infinity (kGhostVertex). The ghost over hull edge a->b (hull taken
// counter-clockwise) is stored as corners (b, a, G):
//
//        side 0: b->a   twin of the real edge a->b (or of the opposite ghost on a flat hull)
//        side 1: a->G   twin of side 2 of the ghost over the previous hull edge
//        side 2: G->b   twin of side 1 of the ghost over the next hull edge
//
// With every sub-triangulation a closed surface, the merge never needs special cases: deleting an
// edge of the left or right half that fails the empty-circle test is an ordinary flip against a
// ghost, and adding a cross triangle turns a ghost into a real triangle by replacing its G corner.
// A triangulation of k points (k+1 with G) has exactly 2k-2 triangles, real and ghost, and a merge
// adds exactly two ghosts (the two bridges), so every recursive call knows in advance which slots
// it owns; the two top halves can be built by two threads with no locking and the same result.
//
// Cut alternation (Dwyer): the points are sorted once along a Morton (Z-order) curve of their
// coordinates quantised to 24 bits on a square grid. A recursive call owns a range of that order
// whose keys share a prefix; it cuts at the first key bit where its points differ, which is a cut
// at the midpoint of its cell, alternately along x and y, found by binary search. The two halves are
// separated by that line, which is all the merge needs; they need not be equal in size. Points that
// share a key (closer than 2^-24 of the extent) are kept in x order and cut vertically. A cut
// leaving a single point on one side moves the nearest point across so that both sides have two.
// Each axis has its own total order (x then y; y then -x) so that a cut along y is a rotation of the
// vertical case and ties are broken the same way.
//
// Cocircular ties: the merge's empty-circle tests are Predicates::incircle_perturbed, which breaks
// an exact zero by a fixed symbolic perturbation of the points, so the triangulation is the unique
// Delaunay triangulation of the perturbed points whatever the cuts and merge order (and -F and -i
// end at the same one). On general-position input no test is zero and nothing changes.
#include "delaunay/divide_and_conquer.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <type_traits>
#include <utility>

#include "mesh/topology_writer.h"
#include "util/run_both.h"

namespace deltri {
namespace {

bool less_on(int axis, const Point& a, const Point& b) {
  return axis == 0 ? (a.x < b.x || (a.x == b.x && a.y < b.y))
                   : (a.y < b.y || (a.y == b.y && a.x > b.x));
}

constexpr std::uint32_t kParallelThreshold = 1u << 15;

// Runs body(from, to) over [0, n), split in two halves on two threads if `parallel`. The stage
// keeps this beside run_halves: with run_halves in these loops the 1M points' stage measured 4-5%
// slower in several builds, the time going to the recursion, whose code had not changed (code
// layout; benchmarks.md).
template <class Body>
void split_in_two(std::size_t n, bool parallel, const Body& body) {
  if (!parallel) return body(std::size_t{0}, n);
  run_both([&] { body(std::size_t{0}, n / 2); }, [&] { body(n / 2, n); });
}

// Splitting work in two pays only when `threads` allows it and there is enough of it.
bool worth_two(int threads, std::size_t n) { return threads > 1 && n >= kParallelThreshold; }

// Spreads the 32 bits of v over the even bits of a 64-bit word.
std::uint64_t spread_bits(std::uint32_t v) {
  std::uint64_t x = v;
  x = (x | (x << 16)) & 0x0000FFFF0000FFFFull;
  x = (x | (x << 8)) & 0x00FF00FF00FF00FFull;
  x = (x | (x << 4)) & 0x0F0F0F0F0F0F0F0Full;
  x = (x | (x << 2)) & 0x3333333333333333ull;
  x = (x | (x << 1)) & 0x5555555555555555ull;
  return x;
}

// Quantises points onto a square 2^24 grid over their bounding box and interleaves the cell
// coordinates (x in the odd bits, so the first cut is vertical). Monotone in each coordinate, so a
// key bit separates points by a line. 24 bits keep the key within 48 bits: three radix passes.
class MortonKey {
 public:
  static constexpr double kCells = 16777215.0;  // 2^24 - 1
  static constexpr std::uint32_t kLastCell = 0xFFFFFFu;
  MortonKey() = default;
  // The bounding box is found by two threads (when `threads` allows) over the two halves, each
  // in a box of its own stack: the two results side by side share a cache line.
  MortonKey(const BigVector<Point>& pts, const std::vector<VertexKind>& kind, int threads) {
    struct Box {
      bool any = false;
      Point lo;
      double hi_x = -1e308, hi_y = -1e308;
    } half[2];
    split_in_two(pts.size(), worth_two(threads, pts.size()), [&](std::size_t from, std::size_t to) {
      Box box;
      for (std::size_t i = from; i < to; ++i) {
        if (kind[i] != VertexKind::Input) continue;
        const Point& p = pts[i];
        if (!box.any) box.lo = p, box.any = true;
        box.lo.x = std::min(box.lo.x, p.x), box.lo.y = std::min(box.lo.y, p.y);
        box.hi_x = std::max(box.hi_x, p.x), box.hi_y = std::max(box.hi_y, p.y);
      }
      half[from == 0 ? 0 : 1] = box;
    });
    for (const Box& box : half) {
      if (!box.any) continue;
      if (!any_) lo_ = box.lo, any_ = true;
      lo_.x = std::min(lo_.x, box.lo.x), lo_.y = std::min(lo_.y, box.lo.y);
      hi_x_ = std::max(hi_x_, box.hi_x), hi_y_ = std::max(hi_y_, box.hi_y);
    }
    // Coordinates near both ends of the double range overflow their differences (and then
    // inf * 0 made NaN cells, which broke the keys' monotonicity and the merge: issue 17). Halving
    // first keeps every difference finite; it is monotone, which is all the keys need.
    if (!std::isfinite(hi_x_ - lo_.x) || !std::isfinite(hi_y_ - lo_.y)) half_ = 0.5;
    const double extent = std::max(hi_x_ * half_ - lo_.x * half_, hi_y_ * half_ - lo_.y * half_);
    scale_ = extent > 0.0 ? kCells / extent : 0.0;
  }
  std::uint64_t operator()(const Point& p) const {
    return (spread_bits(cell(p.x * half_ - lo_.x * half_)) << 1) | spread_bits(cell(p.y * half_ - lo_.y * half_));
  }

 private:
  std::uint32_t cell(double d) const {
    const double c = d * scale_;
    if (!(c > 0.0)) return 0;  // also NaN: a cast of NaN would be undefined
    return c >= kCells ? kLastCell : static_cast<std::uint32_t>(c);
  }
  bool any_ = false;
  Point lo_;
  double hi_x_ = -1e308, hi_y_ = -1e308;
  double scale_ = 0.0;
  double half_ = 1.0;
};

// The empty constructor leaves the members uninitialised, so that large arrays of these are not
// zero-filled by one thread before being overwritten (their pages are then first touched by the
// threads that fill them).
struct KeyedVertex {
  KeyedVertex() {}  // NOLINT: deliberately not "= default", which would zero-fill
  KeyedVertex(std::uint64_t k, VertexId v) : key(k), id(v) {}
  std::uint64_t key;
  VertexId id;
};

constexpr std::size_t kDigits = 65536;
unsigned digit(const KeyedVertex& k, int d) { return static_cast<unsigned>(k.key >> (16 * d)) & 0xFFFF; }

// LSD radix sort on the 48-bit key, 16 bits at a time, skipping digits all keys share. With two
// threads each pass counts and moves the two halves of the array at once; the first half's keys
// go before the second's in every bucket, so the sort stays stable and the result is the same.
void radix_sort(BigVector<KeyedVertex>& items, int threads) {
  const std::size_t n = items.size();
  // Below this many items clearing the counts (0.5 MiB, three times) costs more than sorting:
  // a stable sort on the same 48 bits gives the same order.
  if (n < kDigits / 8) {
    constexpr std::uint64_t low48 = (std::uint64_t{1} << 48) - 1;
    std::stable_sort(items.begin(), items.end(),
                     [](const KeyedVertex& a, const KeyedVertex& b) { return (a.key & low48) < (b.key & low48); });
    return;
  }
  const bool two = worth_two(threads, n);
  BigVector<KeyedVertex> buffer(n);
  std::vector<std::uint32_t> count(2 * kDigits);
  for (int d = 0; d < 3; ++d) {
    std::fill(count.begin(), count.end(), 0u);
    split_in_two(n, two, [&](std::size_t from, std::size_t to) {
      std::uint32_t* c = &count[from == 0 ? 0 : kDigits];
      for (std::size_t k = from; k < to; ++k) ++c[digit(items[k], d)];
    });
    std::uint32_t sum = 0;
    bool one_bucket = false;
    for (std::size_t i = 0; i < kDigits; ++i) {
      one_bucket = one_bucket || count[i] + count[kDigits + i] == n;
      sum += std::exchange(count[i], sum);
      sum += std::exchange(count[kDigits + i], sum);
    }
    if (one_bucket) continue;  // nothing to reorder
    split_in_two(n, two, [&](std::size_t from, std::size_t to) {
      std::uint32_t* c = &count[from == 0 ? 0 : kDigits];
      for (std::size_t k = from; k < to; ++k) buffer[c[digit(items[k], d)]++] = items[k];
    });
    items.swap(buffer);
  }
}

// --- the triangulation builder ---

// The builder keeps raw arrays (issue 20 allows this one file to): it fills slots 3t..3t+2 of
// its triangles by hand, so inside it the ids are plain integers and lnext, lprev, triangle_of and
// edge_of (3t + i) are its own. The mesh's arrays of Id<...> are read through std::uint32_t
// pointers, which raw() checks is the same layout.
class Builder {
  using VertexId = std::uint32_t;
  using TriangleId = std::uint32_t;
  using EdgeRef = std::uint32_t;
  static constexpr EdgeRef lnext(EdgeRef e) { return e % 3 == 2 ? e - 2 : e + 1; }
  static constexpr EdgeRef lprev(EdgeRef e) { return e % 3 == 0 ? e + 2 : e - 1; }
  static constexpr TriangleId triangle_of(EdgeRef e) { return e / 3; }
  static constexpr EdgeRef edge_of(TriangleId t, unsigned side) { return 3 * t + side; }

 public:
  // `key` null: vertical cuts at the median of points in x order (-l).
  Builder(Point* pts, deltri::VertexId* order, BigVector<deltri::VertexId>& corner, BigVector<deltri::EdgeRef>& link,
          const MortonKey* key)
      : Builder(pts, order, raw(corner), raw(link), key) {}
  Builder(Point* pts, deltri::VertexId* order, VertexId* corner, EdgeRef* link, const MortonKey* key)
      : p_(pts), order_(order), corner_(corner), link_(link), key_(key) {}

  // Triangulates sites [lo, lo+n) into triangle slots starting at `slot` and returns a ghost
  // triangle of the hull ring.
  TriangleId build(std::uint32_t lo, std::uint32_t n, TriangleId slot, int threads) {
    if (n == 2) return base_two(lo, slot);
    if (n == 3) return base_three(lo, slot);
    const auto [half, axis] = choose_cut(lo, n);
    const TriangleId right_slot = slot + 2 * half - 2;
    TriangleId left, right;
    if (threads > 1 && n >= kParallelThreshold) {
      // The worker's builder lives on the worker's stack: its predicate counters, written at every
      // test, would share a cache line with this thread's stack.
      PredicateCounters counted;
      // Init-captures: clang before 16 cannot capture a structured binding (the fuzz build).
      run_both(
          [&, half = half] {
            Builder other(p_, order_, corner_, link_, key_);
            left = other.build(lo, half, slot, threads / 2);
            counted = other.pred.counters;
          },
          [&, half = half] { right = build(lo + half, n - half, right_slot, threads - threads / 2); });
      pred.counters.add(counted);
    } else {
      left = build(lo, half, slot, 1);
      right = build(lo + half, n - half, right_slot, 1);
    }
    return merge(left, right, axis, slot + 2 * n - 4);
  }

  Predicates pred;

 private:
  template <class Tag>
  static std::uint32_t* raw(BigVector<Id<Tag>>& ids) {
    static_assert(sizeof(Id<Tag>) == sizeof(std::uint32_t) && std::is_standard_layout_v<Id<Tag>>);
    return reinterpret_cast<std::uint32_t*>(ids.data());
  }

  Point* p_;
  deltri::VertexId* order_;
  VertexId* corner_;
  EdgeRef* link_;
  const MortonKey* key_;

  struct Cut {
    std::uint32_t half;  // size of the lower part
    int axis;            // 0: the parts are separated along x, 1: along y
  };

  Cut choose_cut(std::uint32_t lo, std::uint32_t n) {
    if (!key_) return {n / 2, 0};
    const std::uint64_t differ = (*key_)(p_[lo]) ^ (*key_)(p_[lo + n - 1]);
    if (differ == 0) return {n / 2, 0};  // one grid cell: kept in x order
    const int bit = 63 - std::countl_zero(differ);
    const std::uint64_t mask = std::uint64_t{1} << bit;
    std::uint32_t first = 1, last = n - 1;  // the first point with the bit set is in [1, n-1]
    while (first < last) {
      const std::uint32_t mid = first + (last - first) / 2;
      if ((*key_)(p_[lo + mid]) & mask) last = mid; else first = mid + 1;
    }
    const int axis = (bit & 1) ? 0 : 1;
    if (first == 1) move_extreme(lo + 1, n - 1, axis, false, lo + 1), first = 2;
    else if (first == n - 1) move_extreme(lo, n - 1, axis, true, lo + n - 2), first = n - 2;
    return {first, axis};
  }

  // Moves the smallest (or largest) point of [lo, lo+n) along `axis` to position `to`, keeping the
  // others in order, so that a side of one point can borrow its nearest neighbour across the cut.
  void move_extreme(std::uint32_t lo, std::uint32_t n, int axis, bool largest, std::uint32_t to) {
    std::uint32_t best = lo;
    for (std::uint32_t i = lo + 1; i < lo + n; ++i) {
      if (largest ? less_on(axis, p_[best], p_[i]) : less_on(axis, p_[i], p_[best])) best = i;
    }
    if (best < to) {
      std::rotate(p_ + best, p_ + best + 1, p_ + to + 1);
      std::rotate(order_ + best, order_ + best + 1, order_ + to + 1);
    } else if (best > to) {
      std::rotate(p_ + to, p_ + best, p_ + best + 1);
      std::rotate(order_ + to, order_ + best, order_ + best + 1);
    }
  }

  void bond(EdgeRef a, EdgeRef b) {
    link_[a] = b;
    link_[b] = a;
  }
  void set_corners(TriangleId t, VertexId a, VertexId b, VertexId c) {
    corner_[edge_of(t, 0)] = a;
    corner_[edge_of(t, 1)] = b;
    corner_[edge_of(t, 2)] = c;
  }
  // Ghost over hull edge a->b.
  void make_ghost(TriangleId g, VertexId a, VertexId b) { set_corners(g, b, a, kGhostVertex); }
  TriangleId next_ghost(TriangleId g) const { return triangle_of(link_[edge_of(g, 2)]); }
  TriangleId prev_ghost(TriangleId g) const { return triangle_of(link_[edge_of(g, 1)]); }
  // Links ghosts g[0..k) into a ring in hull order.
  void close_ring(const TriangleId* g, unsigned k) {
    for (unsigned i = 0; i < k; ++i) bond(edge_of(g[i], 2), edge_of(g[(i + 1) % k], 1));
  }

  TriangleId base_two(VertexId a, TriangleId slot) {
    const TriangleId g[2] = {slot, slot + 1};
    make_ghost(g[0], a, a + 1);
    make_ghost(g[1], a + 1, a);
    bond(edge_of(g[0], 0), edge_of(g[1], 0));
    close_ring(g, 2);
    return g[0];
  }

  TriangleId base_three(VertexId a, TriangleId slot) {
    const VertexId b = a + 1, c = a + 2;
    // A flat triple must be in order along its line.
    for (VertexId i : {a, b, a})
      if (less_on(0, p_[i + 1], p_[i])) std::swap(p_[i], p_[i + 1]), std::swap(order_[i], order_[i + 1]);
    const double o = pred.orient2d(p_[a], p_[b], p_[c]);
    if (o == 0.0) {  // a flat hull a->b->c->b->a
      const TriangleId g[4] = {slot, slot + 1, slot + 2, slot + 3};
      make_ghost(g[0], a, b);
      make_ghost(g[1], b, c);
      make_ghost(g[2], c, b);
      make_ghost(g[3], b, a);
      bond(edge_of(g[0], 0), edge_of(g[3], 0));
      bond(edge_of(g[1], 0), edge_of(g[2], 0));
      close_ring(g, 4);
      return g[0];
    }
    const VertexId h[3] = {a, o > 0.0 ? b : c, o > 0.0 ? c : b};
    const TriangleId t = slot;
    set_corners(t, h[0], h[1], h[2]);
    const TriangleId g[3] = {slot + 1, slot + 2, slot + 3};
    for (unsigned i = 0; i < 3; ++i) {
      make_ghost(g[i], h[i], h[(i + 1) % 3]);
      bond(edge_of(g[i], 0), edge_of(t, i));
    }
    close_ring(g, 3);
    return g[0];
  }

  // The ghost over the hull edge entering the extreme vertex of the ring along `axis` (largest if
  // `largest`, else smallest), entering or leaving it as `entering` says. Along a convex ring the
  // order on `axis` (a linear order with ties broken by the other coordinate) rises once and falls
  // once, so walking from `start` in the direction that improves finds the extreme without going
  // round: with long hulls (grids) the full round cost a twentieth of the triangulation.
  TriangleId extreme_ghost(TriangleId start, int axis, bool largest, bool entering) const {
    const auto vertex = [&](TriangleId g) { return entering ? corner_[edge_of(g, 0)] : corner_[edge_of(g, 1)]; };
    const auto better = [&](TriangleId g, TriangleId than) {
      const Point &p = p_[vertex(g)], &q = p_[vertex(than)];
      return largest ? less_on(axis, q, p) : less_on(axis, p, q);
    };
    TriangleId best = start;
    for (TriangleId g = next_ghost(best); g != start && better(g, best); g = next_ghost(g)) best = g;
    if (best != start) return best;
    for (TriangleId g = prev_ghost(best); g != start && better(g, best); g = prev_ghost(g)) best = g;
    return best;
  }

  // Removes the edge between ghost g's side 0 and the real triangle behind it by a flip, so that the
  // region above the merge base grows by that triangle. `left` says which half g belongs to; the
  // return value is the ghost that now carries the base's candidate edge. g's side towards the base
  // (side 1 on the left, side 2 on the right) is detached during the merge and stays so.
  TriangleId delete_by_flip(TriangleId g, bool left) {
    const EdgeRef e = edge_of(g, 0), f = link_[e];
    const TriangleId t = triangle_of(f);
    const EdgeRef f1 = lnext(f), f2 = lprev(f);
    const VertexId far = corner_[f2];
    const EdgeRef out_f1 = link_[f1], out_f2 = link_[f2];
    if (left) {
      // g = (x, l, G), t = (l, x, x2)  ->  g = (x2, l, G), t = (x, x2, G)
      const EdgeRef out_g2 = link_[e + 2];
      const VertexId x = corner_[e], l = corner_[e + 1];
      set_corners(g, far, l, kGhostVertex);
      set_corners(t, x, far, kGhostVertex);
      bond(e, out_f2);
      bond(e + 2, edge_of(t, 1));
      bond(edge_of(t, 0), out_f1);
      bond(edge_of(t, 2), out_g2);
      return g;
    }
    // g = (r, y, G), t = (y, r, y2)  ->  g = (r, y2, G), t = (y2, y, G)
    const EdgeRef out_g1 = link_[e + 1];
    const VertexId r = corner_[e], y = corner_[e + 1];
    set_corners(g, r, far, kGhostVertex);
    set_corners(t, far, y, kGhostVertex);
    bond(e, out_f1);
    bond(e + 1, edge_of(t, 2));
    bond(edge_of(t, 0), out_f2);
    bond(edge_of(t, 1), out_g1);
    return g;
  }

  TriangleId merge(TriangleId left_ring, TriangleId right_ring, int axis, TriangleId slot);
};

// Guibas-Stolfi merge. The base edge l->r starts as the lower common tangent and climbs until it
// becomes the upper one; the region above it is bounded by ghost triangles of both halves, `gl`
// and `gr` being those on the base's ends.
Builder::TriangleId Builder::merge(TriangleId left_ring, TriangleId right_ring, int axis, TriangleId slot) {
  // Lower common tangent: walk l clockwise around the left hull and r counter-clockwise around the
  // right hull while the other end sees past the current hull edge.
  TriangleId in_l = extreme_ghost(left_ring, axis, true, true);      // ghost over w->l
  TriangleId out_r = extreme_ghost(right_ring, axis, false, false);  // ghost over r->s
  while (true) {
    const VertexId l = corner_[edge_of(in_l, 0)], w = corner_[edge_of(in_l, 1)];
    const VertexId r = corner_[edge_of(out_r, 1)], s = corner_[edge_of(out_r, 0)];
    if (pred.orient2d(p_[l], p_[w], p_[r]) > 0.0) {
      in_l = prev_ghost(in_l);
    } else if (pred.orient2d(p_[r], p_[s], p_[l]) < 0.0) {
      out_r = next_ghost(out_r);
    } else {
      break;
    }
  }
  TriangleId gl = next_ghost(in_l);   // (x, l, G): its side 0 x->l is the left candidate edge
  TriangleId gr = prev_ghost(out_r);  // (r, y, G): its side 0 r->y is the right candidate edge
  VertexId l = corner_[edge_of(in_l, 0)], r = corner_[edge_of(out_r, 1)];

  const TriangleId bottom = slot;
  make_ghost(bottom, l, r);
  link_[edge_of(gl, 1)] = kNone;
  link_[edge_of(gr, 2)] = kNone;
  bond(edge_of(bottom, 1), edge_of(in_l, 2));
  bond(edge_of(bottom, 2), edge_of(out_r, 1));
  EdgeRef pending = edge_of(bottom, 0);  // the edge r->l below the base, waiting for the triangle above

  while (true) {
    VertexId x = corner_[edge_of(gl, 0)];
    const bool left_ok = pred.orient2d(p_[l], p_[r], p_[x]) > 0.0;
    if (left_ok) {
      while (true) {
        const VertexId x2 = corner_[lprev(link_[edge_of(gl, 0)])];
        if (x2 == kGhostVertex || pred.incircle_perturbed(p_[l], p_[r], p_[x], p_[x2]) <= 0.0) break;
        gl = delete_by_flip(gl, true);
        x = x2;
      }
    }
    VertexId y = corner_[edge_of(gr, 1)];
    const bool right_ok = pred.orient2d(p_[l], p_[r], p_[y]) > 0.0;
    if (right_ok) {
      while (true) {
        const VertexId y2 = corner_[lprev(link_[edge_of(gr, 0)])];
        if (y2 == kGhostVertex || pred.incircle_perturbed(p_[l], p_[r], p_[y], p_[y2]) <= 0.0) break;
        gr = delete_by_flip(gr, false);
        y = y2;
      }
    }
    if (!left_ok && !right_ok) break;
    if (!left_ok || (right_ok && pred.incircle_perturbed(p_[l], p_[r], p_[x], p_[y]) > 0.0)) {
      // Cross triangle (r, y, l) from the right ghost; the new base is l->y.
      const EdgeRef ring = link_[edge_of(gr, 1)];
      corner_[edge_of(gr, 2)] = l;
      bond(edge_of(gr, 2), pending);
      pending = edge_of(gr, 1);
      link_[pending] = kNone;
      gr = triangle_of(ring);
      link_[ring] = kNone;
      r = y;
    } else {
      // Cross triangle (x, l, r) from the left ghost; the new base is x->r.
      const EdgeRef ring = link_[edge_of(gl, 2)];
      corner_[edge_of(gl, 2)] = r;
      bond(edge_of(gl, 1), pending);
      pending = edge_of(gl, 2);
      link_[pending] = kNone;
      gl = triangle_of(ring);
      link_[ring] = kNone;
      l = x;
    }
  }
  const TriangleId top = slot + 1;
  make_ghost(top, r, l);
  bond(edge_of(top, 0), pending);
  bond(edge_of(top, 1), edge_of(gr, 2));
  bond(edge_of(top, 2), edge_of(gl, 1));
  return bottom;
}

// --- preparing sites and finishing the mesh ---

bool lexicographic_less(const Point& a, VertexId ia, const Point& b, VertexId ib) {
  return a.x < b.x || (a.x == b.x && (a.y < b.y || (a.y == b.y && ia < ib)));
}

// The Input vertices along the Morton curve (key null: all in one group of equal keys), to be put
// in the order the recursion wants by order_groups_and_remove_duplicates.
BigVector<KeyedVertex> order_vertices(const Mesh& mesh, const MortonKey* key, int threads) {
  const std::size_t n = mesh.vertex_count();
  const bool two = worth_two(threads, n);
  std::size_t first_half = 0, all = 0;  // Input vertices in [0, n/2), in [0, n)
  for (VertexId v{0}; v < n; ++v) {
    if (v == n / 2) first_half = all;
    all += mesh.kind[v] == VertexKind::Input;
  }
  if (!two) first_half = 0;
  BigVector<KeyedVertex> items(all);
  split_in_two(n, two, [&](std::size_t from, std::size_t to) {
    std::size_t k = from == 0 ? 0 : first_half;
    for (std::size_t v = from; v < to; ++v)
      if (mesh.kind[v] == VertexKind::Input) items[k++] = {key ? (*key)(mesh.points[v]) : 0, static_cast<VertexId>(v)};
  });
  if (key) radix_sort(items, threads);
  return items;
}

// sorted[k] = points[items[k].id], order[k] = items[k].id; the random reads are split over threads.
void gather(const BigVector<Point>& points, const BigVector<KeyedVertex>& items,
            BigVector<Point>& sorted, BigVector<VertexId>& order, int threads) {
  split_in_two(items.size(), worth_two(threads, items.size()), [&](std::size_t from, std::size_t to) {
    for (std::size_t k = from; k < to; ++k) {
      sorted[k] = points[items[k].id];
      order[k] = items[k].id;
    }
  });
}

// Puts each group of equal keys in x order and drops all but the first of each run of equal points,
// reporting them; one pass, because at 4M points every pass over the keys costs 10 ms on one core.
void order_groups_and_remove_duplicates(const Mesh& mesh, BigVector<KeyedVertex>& items,
                                        std::vector<std::pair<VertexId, VertexId>>& duplicates) {
  const auto by_point = [&](const KeyedVertex& a, const KeyedVertex& b) {
    return lexicographic_less(mesh.points[a.id], a.id, mesh.points[b.id], b.id);
  };
  std::size_t kept = 0;
  for (std::size_t i = 0; i < items.size();) {
    std::size_t j = i + 1;
    while (j < items.size() && items[j].key == items[i].key) ++j;
    if (j - i == 1) {
      items[kept++] = items[i];
      i = j;
      continue;
    }
    std::sort(items.begin() + static_cast<std::ptrdiff_t>(i), items.begin() + static_cast<std::ptrdiff_t>(j), by_point);
    items[kept++] = items[i];  // equal points are adjacent now, the lowest id first
    for (std::size_t k = i + 1; k < j; ++k) {
      if (mesh.points[items[k].id] == mesh.points[items[kept - 1].id]) duplicates.emplace_back(items[k].id, items[kept - 1].id);
      else items[kept++] = items[k];
    }
    i = j;
  }
  items.resize(kept);
  std::sort(duplicates.begin(), duplicates.end());
}

// Buckets of 2^14 destinations (320 KiB of points and ids) stay in a core's L2 cache.
constexpr unsigned kBucketShift = 14;

// Moves points[k] to position order[k] for every k < n, in place; order is a permutation of
// [0, n) and is consumed. Cycles followed across the whole array miss the cache and the TLB at
// every step, and each step waits for the one before. So a first pass (American flag sort on the
// destination's bucket) only moves each point into its destination's bucket, writing at one
// advancing position per bucket; then each bucket goes through a small buffer, from which every
// point is stored at its place independently of the others.
void permute_in_place(Point* points, VertexId* order, std::size_t n) {
  const std::size_t buckets = (n >> kBucketShift) + 1;
  const auto bucket_end = [&](std::size_t b) { return std::min(n, (b + 1) << kBucketShift); };
  std::vector<std::size_t> head(buckets);
  for (std::size_t b = 0; b < buckets; ++b) head[b] = b << kBucketShift;
  for (std::size_t b = 0; b < buckets; ++b) {
    for (std::size_t& i = head[b]; i < bucket_end(b);) {
      const std::size_t d = order[i] >> kBucketShift;
      if (d == b) {
        ++i;
        continue;
      }
      while (order[head[d]] >> kBucketShift == d) ++head[d];  // already in its bucket: leave it
      std::swap(points[i], points[head[d]]);
      std::swap(order[i], order[head[d]]);
      ++head[d];
    }
  }
  std::vector<Point> buffer(std::min(n, std::size_t{1} << kBucketShift));
  for (std::size_t b = 0; b < buckets; ++b) {
    const std::size_t lo = b << kBucketShift, hi = bucket_end(b);
    std::copy(points + lo, points + hi, buffer.begin());
    for (std::size_t k = lo; k < hi; ++k) points[order[k]] = buffer[k - lo];
  }
}

// Deletes the ghost triangles and packs the live ones into the first slots.
void remove_ghosts(Mesh& mesh) {
  const std::uint32_t slots = mesh.triangle_slots();
  for (TriangleId t{0}; t < slots; ++t) {
    if (mesh.corner[edge_of(t, 2)] == kGhostVertex) mesh.kill_triangle(t);
  }
  mesh.compact_triangles();
}

}  // namespace

void divide_and_conquer_delaunay(Mesh& mesh, const DivideAndConquerOptions& options,
                                 std::vector<std::pair<VertexId, VertexId>>& duplicates,
                                 PredicateCounters& counters) {
  const int threads = std::max(1, options.threads);
  detail::corner_slots(mesh).clear();
  detail::link_slots(mesh).clear();
  detail::subseg_slots(mesh).clear();
  mesh.free_triangles.clear();

  const MortonKey key(mesh.points, mesh.kind, threads);
  const MortonKey* cut_key = options.alternate_cuts ? &key : nullptr;
  BigVector<KeyedVertex> items = order_vertices(mesh, cut_key, threads);
  order_groups_and_remove_duplicates(mesh, items, duplicates);
  for (const auto& [dup, kept] : duplicates) mesh.kind[dup] = VertexKind::Duplicate;
  const std::uint32_t m = static_cast<std::uint32_t>(items.size());
  if (m < 3) return;

  // Work on a copy of the coordinates in recursion order. The vertex array is released meanwhile
  // (and rebuilt from the copy) so that peak memory stays near 68 bytes per point; the coordinates
  // of vertices that take no part (duplicates, other kinds) are kept aside.
  const std::size_t total = mesh.points.size();
  std::vector<std::pair<VertexId, Point>> bystanders;
  for (VertexId v{0}; v < total; ++v)
    if (mesh.kind[v] != VertexKind::Input) bystanders.emplace_back(v, mesh.points[v]);
  BigVector<Point> sorted;
  BigVector<VertexId> order;
  sorted.reserve(total);
  order.reserve(total);
  sorted.resize(m);
  order.resize(m);
  gather(mesh.points, items, sorted, order, threads);
  BigVector<KeyedVertex>().swap(items);
  BigVector<Point>().swap(mesh.points);

  const std::size_t triangles = 2 * static_cast<std::size_t>(m) - 2, edge_slots = 3 * triangles;
  // Zero-filling the two arrays (and faulting in their pages) is done by a thread each.
  run_both(
      worth_two(threads, m), [&] { detail::corner_slots(mesh).resize(edge_slots); },
      [&] { detail::link_slots(mesh).resize(edge_slots); });
  Builder builder(sorted.data(), order.data(), detail::corner_slots(mesh), detail::link_slots(mesh), cut_key);
  builder.build(0, m, 0, threads);
  counters.add(builder.pred.counters);

  split_in_two(mesh.corner.size(), worth_two(threads, m), [&](std::size_t from, std::size_t to) {
    for (std::size_t e = from; e < to; ++e)
      if (mesh.corner[e] != kGhostVertex) detail::corner_slots(mesh)[e] = order[mesh.corner[e]];
  });
  // The bystanders' ids complete the permutation: their slots past m are empty and get the
  // bystanders' coordinates afterwards.
  sorted.resize(total);
  order.resize(total);
  for (std::size_t k = 0; k < bystanders.size(); ++k) order[m + k] = bystanders[k].first;
  // The vertices' order and the triangles' slots are independent: one thread each.
  run_both(
      worth_two(threads, m), [&] { permute_in_place(sorted.data(), order.data(), total); }, [&] { remove_ghosts(mesh); });
  for (const auto& [v, p] : bystanders) sorted[v] = p;
  mesh.points = std::move(sorted);
}

}  // namespace deltri
