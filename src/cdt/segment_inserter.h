// Recovers one cleaned input segment as a chain of constrained edges: splits it at vertices lying
// exactly on it, turns crossings with earlier segments into vertices, and recovers what is left
// with EdgeRecovery. Pieces wait on an explicit stack, so nothing recurses.
#pragma once

#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <unordered_set>
#include <vector>

#include "mesh/constrained_editor.h"
#include "mesh/recover_edge.h"

namespace deltri {

struct Piece {
  VertexId u = kNone, v = kNone;
  int marker = 0;
  std::uint32_t segment = kNone;
};

struct InsertionCounts {
  std::size_t split_at_vertices = 0;
  std::size_t overlaps_merged = 0;
  std::size_t crossings = 0;
  std::size_t unrecovered = 0;
  std::size_t snapped = 0;  // vertices within kSnapUlps of a segment that split it (snap_to_segments)
  std::size_t midpoints = 0;  // -s: vertices inserted at the midpoints of missing pieces
};

// A vertex this many units in the last place or closer to a segment's interior is taken to lie on
// it: a T-junction written in decimal is usually one rounding away from the segment in binary.
// The ulps are those of the largest x and the largest y among the three points, each weighted by
// how much a move along that axis moves the point off the segment's line.
inline constexpr double kSnapUlps = 4.0;

// What a look at the triangulation found for a segment u-v before its turn (look_ahead): the edge
// u->v and its twin, with the apices beside them then, where the segment would be recorded on that
// edge at once (no vertex near enough to snap to); else edge is kNone.
struct EdgeFound {
  EdgeRef edge = kNone, twin = kNone;
  VertexId apex = kNone, twin_apex = kNone;
};

class SegmentInserter {
 public:
  // With snap_to_segments, a vertex within kSnapUlps of the open segment being inserted splits it
  // there, as a vertex exactly on it does (--exact-input turns this off).
  // With split_to_conform (-s), a piece that is not an edge of the triangulation is split at its
  // midpoint, the midpoint inserted as a vertex (Lawson flips, never across a subsegment), and
  // each half treated the same way until every piece is an edge: a conforming insertion, with no
  // edge flipped in to make a constraint (Triangle's -s, after its description).
  SegmentInserter(Mesh& mesh, Predicates& pred, bool snap_to_segments = false, bool split_to_conform = false)
      : ed_(mesh, pred), recovery_(ed_), snap_(snap_to_segments), conform_(split_to_conform) {}

  void insert(const Piece& segment);
  // insert(segment), given what look_ahead found for it before the segments since were inserted:
  // where the triangulation still has that edge with those apices, insert() would record the
  // segment there and do nothing else, so that is done without the search (identical results).
  void insert(const Piece& segment, const EdgeFound& found);
  // The segment's edge, if the triangulation has it now and the segment would be recorded on it
  // at once. Reads only, so several threads may look at segments at once while none inserts.
  EdgeFound look_ahead(const Piece& segment) const;
  // Starts fetching what inserting `found` reads and writes: its slots and the subsegment table's
  // entries, cache misses in arrays of megabytes.
  void fetch(const EdgeFound& found) const;
  const InsertionCounts& counts() const { return counts_; }

 private:
  void process(const Piece& piece);
  // Records piece on the existing edge e, merging with a subsegment already there.
  void record(EdgeRef e, const Piece& piece);
  SubsegmentId new_record(const Piece& piece);
  // The walk from u found constrained edge g crossing the piece: split both at the crossing.
  void split_crossing(const Piece& piece, EdgeRef g);
  // Removes the subsegment of e and queues the two halves of it around vertex w.
  void release(EdgeRef e, VertexId w);
  VertexId place_crossing(const Piece& piece, const Subsegment& old, const Point& p);
  // -s: inserts the midpoint of u-w and queues both halves; false where no double lies strictly
  // between the two ends (the piece is then recovered by flips).
  bool split_at_midpoint(const Piece& piece, VertexId w);
  // One of `candidates` (the corners of an edge the piece crosses, or the apexes beside an edge it
  // runs along) within kSnapUlps of the piece's interior, or kNone.
  VertexId near_vertex(const Piece& piece, std::initializer_list<VertexId> candidates) const;

  ConstrainedEditor ed_;
  EdgeRecovery recovery_;
  InsertionCounts counts_;
  std::vector<Piece> pending_;
  std::vector<EdgeRef> crossed_;
  std::uint32_t last_overlap_ = kNone;  // segment last counted in overlaps_merged
  bool snap_ = false;
  bool conform_ = false;
  // (input segment, vertex) pairs already snapped: each vertex is taken onto each segment at most
  // once, so snapping adds finitely many pieces even where rounded crossings and bent pieces
  // would otherwise offer the same vertex again and again (found with coordinates near 1e300).
  std::unordered_set<std::uint64_t> snapped_pairs_;
};

}  // namespace deltri
