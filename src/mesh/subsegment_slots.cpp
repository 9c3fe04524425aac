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
  if (over_full(count_ + 1, table_.size())) rehash(table_.empty() ? kLeastTable : 2 * table_.size());
  const std::size_t mask = table_.size() - 1;
  std::size_t i = home(static_cast<std::uint32_t>(e));
  while (table_[i].slot != kNone) i = (i + 1) & mask;
  table_[i] = {static_cast<std::uint32_t>(e), s};
  bits_[e >> 6] |= std::uint64_t{1} << (e & 63);
  ++count_;
}

// Backward-shift deletion: the entries after the hole that may move into it do, so lookups never
// meet a tombstone.
void SubsegmentSlots::erase(std::size_t e) {
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
  bits_[e >> 6] &= ~(std::uint64_t{1} << (e & 63));
  --count_;
}

void SubsegmentSlots::rehash(std::size_t capacity) {
  std::vector<Entry> old;
  old.swap(table_);
  table_.assign(capacity, Entry{kNone, SubsegmentId{kNone}});
  shift_ = 32 - static_cast<unsigned>(std::countr_zero(capacity));
  mask_ = capacity - 1;
  const std::size_t mask = mask_;
  for (const Entry& x : old) {
    if (x.slot == kNone) continue;
    std::size_t i = home(x.slot);
    while (table_[i].slot != kNone) i = (i + 1) & mask;
    table_[i] = x;
  }
}

void SubsegmentSlots::assign(std::size_t n) {
  *this = SubsegmentSlots{};
  resize(n);
}

void SubsegmentSlots::resize(std::size_t n) {
  if (n < size_) {
    std::vector<std::uint32_t> dropped;
    for_each([&](EdgeRef e, SubsegmentId) {
      if (e >= n) dropped.push_back(e);
    });
    erase_all(dropped);
  }
  bits_.resize((n + 63) / 64, 0);
  size_ = n;
  // A table left mostly empty by the drops is rebuilt at its fitting size.
  if (8 * count_ < table_.size()) fit();
}

void SubsegmentSlots::fit() {
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
