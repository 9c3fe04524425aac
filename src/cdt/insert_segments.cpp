#include "cdt/insert_segments.h"

#include <algorithm>
#include <cstdint>
#include <unordered_map>

#include "cdt/repeated_segments.h"
#include "cdt/segment_inserter.h"
#include "mesh/subsegments.h"
#include "util/run_both.h"

namespace deltri {

namespace {

// Segments are inserted in blocks: first every segment of the block is looked for among the
// edges, read-only and on two threads (most segments of a fine boundary are edges of its Delaunay
// triangulation already), then they are inserted in input order, each found edge checked to be
// there still and its slots fetched a few segments ahead. The results are those of inserting one
// segment after the other; the block bounds what the look-ups hold.
constexpr std::uint32_t kLookBlock = 32768;
constexpr std::uint32_t kLeastLookShared = 4096;  // fewer are looked up on this thread alone
constexpr std::uint32_t kFetchAhead = 8;

// A repeated segment's non-zero marker reaches the earlier segment's pieces whose marker is 0,
// the same rule as for pieces shared by overlapping segments.
void pass_markers(Mesh& mesh, const std::vector<std::pair<std::uint32_t, int>>& markers) {
  if (markers.empty()) return;
  std::unordered_map<std::uint32_t, int> by_segment;
  for (const auto& [segment, marker] : markers) by_segment.emplace(segment, marker);
  for (Subsegment& s : mesh.subsegments) {
    if (s.marker != 0) continue;
    const auto it = by_segment.find(s.segment);
    if (it != by_segment.end()) s.marker = it->second;
  }
}

}  // namespace

SegmentReport insert_segments(Mesh& mesh, Predicates& pred, const std::vector<Pslg::Segment>& segments,
                              const std::vector<std::pair<VertexId, VertexId>>& duplicates,
                              bool snap_to_segments, bool split_to_conform, int threads) {
  SegmentReport report;
  mesh.enable_subsegments();
  std::vector<VertexId> kept(mesh.vertex_count());
  for (VertexId v{0}; v < kept.size(); ++v) kept[v] = v;
  for (const auto& [dup, original] : duplicates) kept[dup] = original;

  // Clean every segment first: ends remapped, kNone marking the ignored ones.
  std::vector<std::pair<VertexId, VertexId>> ends(segments.size(), {kNone, kNone});
  for (std::uint32_t i = 0; i < segments.size(); ++i) {
    const Pslg::Segment& s = segments[i];
    if (s.a >= kept.size() || s.b >= kept.size()) {
      ++report.invalid_endpoints;
      continue;
    }
    const VertexId a = kept[s.a], b = kept[s.b];
    report.duplicates_remapped += (a != s.a) + (b != s.b);
    if (a == b) ++report.zero_length;
    else ends[i] = {a, b};
  }
  const std::vector<std::uint32_t> repeat_of = find_repeats(ends, mesh.vertex_count());

  mesh.subsegments.reserve(mesh.subsegments.size() + segments.size());
  mesh.reserve_constrained_edges(2 * segments.size());  // both sides of each, split or not
  SegmentInserter inserter(mesh, pred, snap_to_segments, split_to_conform);
  std::vector<std::pair<std::uint32_t, int>> repeated_markers;
  const auto piece = [&](std::uint32_t i) { return Piece{ends[i].first, ends[i].second, segments[i].marker, i}; };
  std::vector<EdgeFound> found;
  for (std::uint32_t block = 0; block < segments.size(); block += kLookBlock) {
    const std::uint32_t end = static_cast<std::uint32_t>(std::min<std::size_t>(segments.size(), block + kLookBlock));
    found.assign(end - block, EdgeFound{});
    run_halves(threads >= 2 && end - block >= kLeastLookShared, block, end, [&](std::uint32_t from, std::uint32_t to, int) {
      for (std::uint32_t i = from; i < to; ++i)
        if (ends[i].first != kNone && repeat_of[i] == kNone) found[i - block] = inserter.look_ahead(piece(i));
    });
    for (std::uint32_t i = block; i < end; ++i) {
      if (i + kFetchAhead < end) inserter.fetch(found[i + kFetchAhead - block]);
      if (ends[i].first == kNone) continue;
      const int marker = segments[i].marker;
      if (repeat_of[i] != kNone) {
        ++report.repeated;
        if (segments[repeat_of[i]].marker == 0 && marker != 0) repeated_markers.emplace_back(repeat_of[i], marker);
        continue;
      }
      inserter.insert(piece(i), found[i - block]);
    }
  }
  pass_markers(mesh, repeated_markers);
  drop_dead_subsegments(mesh);

  const InsertionCounts& counts = inserter.counts();
  report.split_at_vertices = counts.split_at_vertices;
  report.overlaps_merged = counts.overlaps_merged;
  report.crossings = counts.crossings;
  report.unrecovered = counts.unrecovered;
  report.snapped = counts.snapped;
  report.midpoints = counts.midpoints;
  report.subsegments = mesh.subsegments.size();
  return report;
}

}  // namespace deltri
