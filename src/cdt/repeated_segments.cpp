#include "cdt/repeated_segments.h"

#include <algorithm>

namespace deltri {

namespace {

// The earliest segment an entry repeats, given an earlier entry with the same ends.
std::uint32_t origin(const std::vector<std::uint32_t>& repeat_of, std::uint32_t earlier) {
  return repeat_of[earlier] == kNone ? earlier : repeat_of[earlier];
}

// Marks repeats inside one bucket of (larger end, segment index) entries in index order.
void mark_bucket(std::pair<VertexId, std::uint32_t>* first, std::pair<VertexId, std::uint32_t>* last,
                 std::vector<std::uint32_t>& repeat_of) {
  if (last - first <= 16) {  // a vertex degree, normally: compare all pairs
    for (auto* p = first + 1; p != last; ++p)
      for (auto* q = first; q != p; ++q)
        if (q->first == p->first) {
          repeat_of[p->second] = origin(repeat_of, q->second);
          break;
        }
    return;
  }
  // A hub vertex: sort by the other end, keeping index order among equals.
  std::stable_sort(first, last, [](const auto& x, const auto& y) { return x.first < y.first; });
  for (auto* p = first + 1; p != last; ++p)
    if ((p - 1)->first == p->first) repeat_of[p->second] = origin(repeat_of, (p - 1)->second);
}

}  // namespace

std::vector<std::uint32_t> find_repeats(const std::vector<std::pair<VertexId, VertexId>>& ends,
                                        std::uint32_t vertex_count) {
  std::vector<std::uint32_t> start(vertex_count + 1, 0);
  for (const auto& [a, b] : ends)
    if (a != kNone) ++start[std::min(a, b) + 1];
  for (std::uint32_t v = 0; v < vertex_count; ++v) start[v + 1] += start[v];
  std::vector<std::pair<VertexId, std::uint32_t>> slots(start[vertex_count]);
  std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
  for (std::uint32_t i = 0; i < ends.size(); ++i) {
    const auto [a, b] = ends[i];
    if (a != kNone) slots[fill[std::min(a, b)]++] = {std::max(a, b), i};
  }
  std::vector<std::uint32_t> repeat_of(ends.size(), kNone);
  for (std::uint32_t v = 0; v < vertex_count; ++v)
    if (start[v + 1] - start[v] > 1) mark_bucket(&slots[start[v]], &slots[start[v + 1]], repeat_of);
  return repeat_of;
}

}  // namespace deltri
