#include "mesh/subsegment_slots.h"

#include <algorithm>

namespace deltri {
namespace {

// The table is at most 3/4 full, so linear probing's runs stay short; at 8 bytes an entry it costs
// 11 to 21 bytes per set slot as it fills between doublings.
constexpr std::size_t kLeastTable = 64;
bool over_full(std::size_t count, std::size_t capacity) { return 4 * count > 3 * capacity; }

}  // namespace

void SubsegmentSlots::reserve_entries(std::size_t more) {
  if (dense_) return;
  std::size_t capacity = std::max(table_.size(), kLeastTable);
  while (over_full(count_ + more, capacity)) capacity *= 2;
  if (capacity > table_.size()) rehash(capacity);
}

void SubsegmentSlots::set_triangle_slowly(std::size_t e, SubsegmentId s) {
  set(e, s);
  set(e + 1, SubsegmentId{kNone});
  set(e + 2, SubsegmentId{kNone});
}

void SubsegmentSlots::insert(std::size_t e, SubsegmentId s) {
  if (!dense_ && over_full(count_ + 1, table_.size())) {
    if (dense_worthy(count_ + 1))
      make_dense();
    else
      rehash(table_.empty() ? kLeastTable : 2 * table_.size());
  }
  if (dense_) {
    values_[e] = s;
    mark(e);
    return;
  }
  place(static_cast<std::uint32_t>(e), s);
  mark(e);
}

void SubsegmentSlots::place(std::uint32_t e, SubsegmentId s) {
  std::size_t i = home(e);
  while (table_[i].slot != kNone) i = (i + 1) & mask_;
  table_[i] = {e, s};
}

// Backward-shift deletion: the entries after the hole that may move into it do, so lookups never
// meet a tombstone.
void SubsegmentSlots::erase(std::size_t e) {
  if (dense_) return unmark(e);
  const std::size_t mask = table_.size() - 1;
  std::size_t hole = index_of(e);
  for (std::size_t j = (hole + 1) & mask; table_[j].slot != kNone; j = (j + 1) & mask) {
    const std::size_t k = home(table_[j].slot);
    // The entry at j may fill the hole when the hole lies cyclically in [k, j).
    const bool movable = j > hole ? (k <= hole || k > j) : (k <= hole && k > j);
    if (!movable) continue;
    table_[hole] = table_[j];
    hole = j;
  }
  table_[hole].slot = kNone;
  unmark(e);
}

// The table's entries into the dense array, sized for every slot the bits have room for (room
// only: its pages are touched as slots are written).
void SubsegmentSlots::make_dense() {
  values_.reserve(bits_.capacity() * 64);
  values_.resize(bits_.size() * 64);
  for (const Entry& x : table_)
    if (x.slot != kNone) values_[x.slot] = x.id;
  std::vector<Entry>().swap(table_);
  shift_ = 32;
  mask_ = 0;
  dense_ = true;
}

void SubsegmentSlots::make_sparse() {
  BigVector<SubsegmentId> values;
  values.swap(values_);
  dense_ = false;
  std::size_t capacity = kLeastTable;
  while (over_full(count_, capacity)) capacity *= 2;
  rehash(capacity);
  for (SetSlots at(bits_); at.next();) place(static_cast<std::uint32_t>(at.slot), values[at.slot]);
}

void SubsegmentSlots::grow_word() {
  bits_.push_back(0);
  if (!dense_) return;
  if (sparse_worthy()) return make_sparse();
  values_.resize(bits_.size() * 64);
}

void SubsegmentSlots::rehash(std::size_t capacity) {
  std::vector<Entry> old;
  old.swap(table_);
  table_.assign(capacity, Entry{kNone, SubsegmentId{kNone}});
  shift_ = 32 - static_cast<unsigned>(std::countr_zero(capacity));
  mask_ = capacity - 1;
  for (const Entry& x : old)
    if (x.slot != kNone) place(x.slot, x.id);
}

void SubsegmentSlots::assign(std::size_t n) {
  *this = SubsegmentSlots{};
  resize(n);
}

void SubsegmentSlots::resize(std::size_t n) {
  if (n < size_ && dense_) {
    for (std::size_t e = n; e < size_; ++e)
      if (has(e)) unmark(e);
  } else if (n < size_) {
    std::vector<std::uint32_t> dropped;
    for_each([&](EdgeRef e, SubsegmentId) {
      if (e >= n) dropped.push_back(e);
    });
    erase_all(dropped);
  }
  bits_.resize((n + 63) / 64, 0);
  size_ = n;
  if (dense_) values_.resize(bits_.size() * 64);
  // A table left mostly empty by the drops is rebuilt at its fitting size.
  if (dense_ || 8 * count_ < table_.size()) fit();
}

void SubsegmentSlots::fit() {
  if (dense_) {
    if (sparse_worthy()) make_sparse();
    return;
  }
  std::size_t capacity = kLeastTable;
  while (over_full(count_, capacity)) capacity *= 2;
  if (capacity < table_.size()) rehash(capacity);
}

bool operator==(const SubsegmentSlots& a, const SubsegmentSlots& b) {
  if (a.size_ != b.size_ || a.count_ != b.count_) return false;
  for (std::size_t w = 0; w < a.bits_.size(); ++w)
    if (a.bits_[w] != b.bits_[w]) return false;
  bool same = true;
  a.for_each([&](EdgeRef e, SubsegmentId s) { same = same && b.find(e) == s; });
  return same;
}

std::vector<SubsegmentId> SubsegmentSlots::dense() const {
  std::vector<SubsegmentId> out(size_, SubsegmentId{kNone});
  for_each([&](EdgeRef e, SubsegmentId s) { out[e] = s; });
  return out;
}

}  // namespace deltri
