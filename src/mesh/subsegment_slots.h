// Mesh::subseg, the subsegment on each edge slot, kept sparse: almost every edge of a refined mesh
// is unconstrained (about one slot in six carries a subsegment on the holes benchmarks, fewer on
// larger meshes), and a dense 4-byte id per slot was the largest single array of the refinement's
// peak. Two parts:
//   * one bit per slot, set where the slot carries a value, so "is edge e constrained?" (asked
//     in every flip test and cavity step) stays one load: has(e);
//   * an open-addressing hash table (linear probing, keyed by the slot) holding the values of the
//     set slots, read only when the bit is set: operator[];
//   * or, where a quarter of the slots or more carry a value (a thin strip: every triangle has a
//     side on the boundary), a dense array of values by slot instead of the table: there the
//     table cost as much memory, a cache miss per insert and lookup, and doublings that rewrote it
//     whole (a third of the strip's page faults). The array's values are read only where the
//     bit is set, so growing it writes nothing that matters. The mesh goes back to the table
//     once fewer than an eighth of its slots carry a value (a small domain refined by area).
// Readers use it like the array it replaces: subseg[e] (kNone where nothing lies), size(),
// empty(); writes go through Editor, which only Mesh and mesh/topology_writer.h hand out, so that
// only src/mesh/ writes topology. A value is any id but kNone: the halves' cuts store a mark above
// every record id. The table's layout depends on the order of the writes only, never on anything
// else, and no reader walks it in table order, so outputs do not depend on it.
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "mesh/ids.h"
#include "util/big_allocator.h"
#include "util/prefetch.h"

namespace deltri {

struct Mesh;
namespace detail {
struct TopologyWriter;
}

class SubsegmentSlots {
 public:
  using value_type = SubsegmentId;

  // The subsegment on slot e, or kNone.
  SubsegmentId operator[](std::size_t e) const { return has(e) ? find(e) : SubsegmentId{kNone}; }
  // Whether slot e carries a subsegment (or a mark): subseg[e] != kNone, in one load.
  bool has(std::size_t e) const { return (bits_[e >> 6] >> (e & 63)) & 1; }
  // The word of bits holding slot e's, to prefetch.
  const std::uint64_t* bits_at(std::size_t e) const { return &bits_[e >> 6]; }
  // For loops that read the values slot after slot: starts fetching the table entry of the slot
  // kSlotsAhead further on, if it carries one (a bit test), so that its lookup there finds it in
  // cache instead of waiting for memory.
  void fetch_ahead(std::size_t e) const {
    const std::size_t f = e + kSlotsAhead;
    if (f < size_ && has(f)) prefetch(home_of(f));
  }
  // Where the table looks first for slot e's value, to prefetch before a write (nullptr while
  // the table is empty).
  const void* home_of(std::size_t e) const {
    if (!table_.empty()) return &table_[home(static_cast<std::uint32_t>(e))];
    return dense_ && e < values_.size() ? &values_[e] : nullptr;
  }
  // The dense array's storage (empty while the table holds the values), for PageWarmer.
  const BigVector<SubsegmentId>& dense_values() const { return values_; }

  std::size_t size() const { return size_; }  // slots, 0 while the mesh has no segments
  bool empty() const { return size_ == 0; }
  std::size_t count() const { return count_; }  // slots that carry a value
  // Whether some slot carries the value s: one walk over the table, for a question asked once.
  bool holds(SubsegmentId s) const {
    if (dense_) {
      for (SetSlots at(bits_); at.next();)
        if (values_[at.slot] == s) return true;
      return false;
    }
    for (const Entry& x : table_)
      if (x.slot != kNone && x.id == s) return true;
    return false;
  }
  // Bytes held (bits, table and dense array), for the memory accounting in tests and docs.
  std::size_t bytes() const {
    return bits_.capacity() * sizeof(std::uint64_t) + table_.capacity() * sizeof(Entry) +
           values_.capacity() * sizeof(SubsegmentId);
  }
  // Whether the values sit in the dense array (for tests).
  bool is_dense() const { return dense_; }

  // f(e, id) for every slot e that carries a value, e increasing. The values are scattered over
  // the table: a second walk over the bits runs kFetchAhead slots ahead, fetching their entries.
  template <class F>
  void for_each(F&& f) const {
    SetSlots ahead(bits_);
    for (unsigned k = 0; k < kFetchAhead && ahead.next(); ++k) fetch_home(ahead.slot);
    for (SetSlots at(bits_); at.next();) {
      if (ahead.next()) fetch_home(ahead.slot);
      f(EdgeRef{static_cast<std::uint32_t>(at.slot)}, find(at.slot));
    }
  }

  // Equal contents slot by slot (tests compare meshes and snapshots).
  friend bool operator==(const SubsegmentSlots& a, const SubsegmentSlots& b);
  // The dense array, for tests and snapshots.
  std::vector<SubsegmentId> dense() const;

  class Editor;

 private:
  friend struct Mesh;
  friend struct detail::TopologyWriter;

  struct Entry {
    std::uint32_t slot;  // kNone: empty
    SubsegmentId id;
  };

  // The set slots in increasing order: next() moves to the next one (false past the last).
  struct SetSlots {
    explicit SetSlots(const std::vector<std::uint64_t>& bits) : bits(bits) {}
    bool next() {
      while (word == 0) {
        if (++w >= bits.size()) return false;
        word = bits[w];
      }
      slot = w * 64 + static_cast<std::size_t>(std::countr_zero(word));
      word &= word - 1;
      return true;
    }
    const std::vector<std::uint64_t>& bits;
    std::size_t w = static_cast<std::size_t>(-1), slot = 0;
    std::uint64_t word = 0;
  };
  static constexpr unsigned kFetchAhead = 32;
  static constexpr std::size_t kSlotsAhead = 96;  // about 16 set slots on a refined mesh
  void fetch_home(std::size_t e) const { prefetch(home_of(e)); }

  // Slots come in blocks of kBlockSlots: Fibonacci hashing of the block's number picks where its
  // run of homes starts, and the slots of one block have consecutive homes from there. Triangles
  // made one after the other have neighbouring slots, so their entries share cache lines; with
  // every slot hashed apart, a mesh whose every triangle carries a subsegment (a thin strip) paid
  // a cache miss per lookup and per insert in a table of tens of megabytes.
  static constexpr unsigned kBlockBits = 3;
  static constexpr std::uint32_t kBlockSlots = 1u << kBlockBits;
  std::size_t home(std::uint32_t slot) const {
    const std::uint32_t start = ((slot >> kBlockBits) * 0x9E3779B9u) >> shift_;
    return (start + (slot & (kBlockSlots - 1))) & mask_;
  }
  std::size_t index_of(std::size_t e) const {
    const Entry* table = table_.data();
    std::size_t i = home(static_cast<std::uint32_t>(e));
    while (table[i].slot != e) i = (i + 1) & mask_;
    return i;
  }
  SubsegmentId find(std::size_t e) const { return dense_ ? values_[e] : table_[index_of(e)].id; }

  void set(std::size_t e, SubsegmentId s) {
    if (s == kNone) {
      if (has(e)) erase(e);
    } else if (has(e)) {
      (dense_ ? values_[e] : table_[index_of(e)].id) = s;
    } else {
      insert(e, s);
    }
  }
  void mark(std::size_t e) {
    bits_[e >> 6] |= std::uint64_t{1} << (e & 63);
    ++count_;
  }
  void unmark(std::size_t e) {
    bits_[e >> 6] &= ~(std::uint64_t{1} << (e & 63));
    --count_;
  }
  // The densities where the values move to the dense array (at a rehash) and back to the table
  // (as slots are added): a quarter and an eighth of the slots, apart so that a mesh near one
  // does not move back and forth.
  bool dense_worthy(std::size_t count) const { return 4 * count >= size_; }
  bool sparse_worthy() const { return 8 * count_ < size_; }
  void make_dense();
  void make_sparse();
  // Slots e, e + 1, e + 2 (one triangle's) get s, kNone, kNone: the common case, no value before
  // and none after, costs one test.
  void set_triangle(std::size_t e, SubsegmentId s) {
    const unsigned at = e & 63;
    if (s == kNone && at <= 61 && (bits_[e >> 6] & (std::uint64_t{7} << at)) == 0) return;
    set_triangle_slowly(e, s);
  }
  void set_triangle_slowly(std::size_t e, SubsegmentId s);
  // write(item) for each item listed, in order, with the table entry of slot_of(item) fetched
  // kFetchAhead items ahead: one by one, each write waited for a cache miss in a table of megabytes.
  template <class List, class SlotOf, class Write>
  void write_fetching_ahead(const List& list, SlotOf slot_of, Write write) {
    const std::size_t n = std::size(list);
    for (std::size_t i = 0; i < n && i < kFetchAhead; ++i) fetch_home(slot_of(list[i]));
    for (std::size_t i = 0; i < n; ++i) {
      if (i + kFetchAhead < n) fetch_home(slot_of(list[i + kFetchAhead]));
      write(list[i]);
    }
  }
  // set(e, s) for each (e, s) listed, in order.
  template <class Pairs>
  void set_all(const Pairs& pairs) {
    reserve_entries(std::size(pairs));
    write_fetching_ahead(pairs, [](const auto& p) { return p.first; }, [this](const auto& p) { set(p.first, p.second); });
  }
  // set(e, kNone) for each slot listed.
  template <class Slots>
  void erase_all(const Slots& slots) {
    write_fetching_ahead(slots, [](auto e) { return e; }, [this](auto e) {
      if (has(e)) erase(e);
    });
  }
  // Room in the table for `more` entries beyond those held, without a rehash on the way.
  void reserve_entries(std::size_t more);
  void insert(std::size_t e, SubsegmentId s);
  // Puts (e, s) at its first free place from its home, nothing else.
  void place(std::uint32_t e, SubsegmentId s);
  void erase(std::size_t e);
  void rehash(std::size_t capacity);
  // Slot count n, every slot empty.
  void assign(std::size_t n);
  // Slot count n: new slots empty, slots from n on dropped.
  void resize(std::size_t n);
  // Three more empty slots (a triangle appended).
  void grow_triangle() {
    size_ += 3;
    if (size_ > bits_.size() * 64) grow_word();
  }
  // Another word of bits, and with it the dense array's room or the move back to the table.
  void grow_word();
  void reserve(std::size_t n) {
    bits_.reserve((n + 63) / 64);
    if (dense_) values_.reserve(bits_.capacity() * 64);
  }
  // The table at the least size that holds its entries (after many were cleared).
  void fit();
  // Replaces every value s by f(s); a kNone result clears the slot.
  template <class F>
  void remap(F&& f);
  void clear() { *this = SubsegmentSlots{}; }

  std::vector<std::uint64_t> bits_;
  std::vector<Entry> table_;  // a power of two in size, or empty (always, while dense_)
  BigVector<SubsegmentId> values_;  // while dense_: a value per slot, 64 per word of bits
  bool dense_ = false;
  unsigned shift_ = 32;       // 32 - log2(table_.size())
  std::size_t mask_ = 0;      // table_.size() - 1
  std::size_t size_ = 0;
  std::size_t count_ = 0;
};

// Write access for the kernel (Mesh's members and mesh/topology_writer.h's subseg_slots).
class SubsegmentSlots::Editor {
 public:
  void set(std::size_t e, SubsegmentId s) { slots_->set(e, s); }
  void set_triangle(std::size_t e, SubsegmentId s) { slots_->set_triangle(e, s); }
  template <class Slots>
  void erase_all(const Slots& slots) {
    slots_->erase_all(slots);
  }
  template <class Pairs>
  void set_all(const Pairs& pairs) {
    slots_->set_all(pairs);
  }
  void reserve_entries(std::size_t more) { slots_->reserve_entries(more); }
  void assign(std::size_t n) { slots_->assign(n); }
  void resize(std::size_t n) { slots_->resize(n); }
  void clear() { slots_->clear(); }
  void fit() { slots_->fit(); }
  template <class F>
  void remap(F&& f) {
    slots_->remap(f);
  }

 private:
  friend struct Mesh;
  friend struct detail::TopologyWriter;
  explicit Editor(SubsegmentSlots& s) : slots_(&s) {}
  SubsegmentSlots* slots_;
};

template <class F>
void SubsegmentSlots::remap(F&& f) {
  std::vector<std::uint32_t> cleared;
  if (dense_) {
    for (SetSlots at(bits_); at.next();) {
      values_[at.slot] = f(values_[at.slot]);
      if (values_[at.slot] == kNone) cleared.push_back(static_cast<std::uint32_t>(at.slot));
    }
    erase_all(cleared);
    return;
  }
  for (Entry& x : table_) {
    if (x.slot == kNone) continue;
    x.id = f(x.id);
    if (x.id == kNone) cleared.push_back(x.slot);
  }
  erase_all(cleared);
}

}  // namespace deltri
