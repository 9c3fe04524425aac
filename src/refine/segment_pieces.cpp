#include "refine/segment_pieces.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "geometry/constructions.h"
#include "refine/bottom_scale.h"

namespace deltri {

VertexId shared_end(const PieceEnds& mine, const PieceEnds& other) {
  const auto has = [&](VertexId v) { return v == other[0] || v == other[1]; };
  if (has(mine[0]) && has(mine[1])) return kNone;  // the same piece
  if (has(mine[0])) return mine[0];
  if (has(mine[1])) return mine[1];
  return kNone;
}

std::vector<char> straight_chain_vertices(const Mesh& mesh) {
  const std::size_t n = mesh.vertex_count();
  std::vector<std::uint8_t> degree(n, 0);
  std::vector<std::array<VertexId, 2>> far(n, {kNone, kNone});
  for (const Subsegment& sub : mesh.subsegments) {
    if (sub.a >= n || sub.b >= n || sub.a == sub.b) continue;
    for (const auto& [v, w] : {std::pair{sub.a, sub.b}, std::pair{sub.b, sub.a}}) {
      if (degree[v] < 2) far[v][degree[v]] = w;
      if (degree[v] < 3) ++degree[v];
    }
  }
  std::vector<char> straight(n, 0);
  for (VertexId v{0}; v < n; ++v) {
    if (degree[v] != 2 || far[v][0] == far[v][1]) continue;
    const Point& p = mesh.point(v);
    const Point& u = mesh.point(far[v][0]);
    const Point& w = mesh.point(far[v][1]);
    const double ux = u.x - p.x, uy = u.y - p.y, wx = w.x - p.x, wy = w.y - p.y;
    if (!(ux * wx + uy * wy < 0.0)) continue;  // not opposite directions
    if (at_bottom_scale(ux * ux + uy * uy, p) || at_bottom_scale(wx * wx + wy * wy, p)) continue;
    const double lx = w.x - u.x, ly = w.y - u.y;
    const double off = std::fabs(lx * (p.y - u.y) - ly * (p.x - u.x)) / std::hypot(lx, ly);  // p's distance to line uw
    straight[v] = off <= ulps_at(magnitude(p), kStraightChainUlps);
  }
  return straight;
}

namespace {

// Walks on from vertex v beyond subsegment record `from` while the vertices are straight, marking
// and collecting the records passed; returns the chain's end on that side (a closed loop of
// straight vertices ends where it meets a record already done).
VertexId walk_straight(const Mesh& mesh, const std::vector<char>& straight,
                       const std::vector<std::array<std::uint32_t, 2>>& at, VertexId v, std::uint32_t from,
                       std::vector<char>& done, std::vector<std::uint32_t>& chain) {
  const std::size_t n = mesh.vertex_count();
  while (v < n && straight[v]) {
    const std::uint32_t next = at[v][0] == from ? at[v][1] : at[v][0];
    if (next == UINT32_MAX || done[next]) break;
    done[next] = 1;
    chain.push_back(next);
    const Subsegment& s = mesh.subsegments[next];
    v = s.a == v ? s.b : s.a;
    from = next;
  }
  return v;
}

}  // namespace

namespace {

// The subsegments' far ends at each vertex, in compressed rows: at[first[v]] .. at[first[v + 1]].
struct SubsegmentNeighbours {
  std::vector<std::uint32_t> first;
  std::vector<VertexId> at;
  explicit SubsegmentNeighbours(const Mesh& mesh) {
    const std::size_t n = mesh.vertex_count();
    first.assign(n + 1, 0);
    for (const Subsegment& s : mesh.subsegments)
      if (s.a < n && s.b < n && s.a != s.b) ++first[s.a + 1], ++first[s.b + 1];
    for (std::size_t v = 0; v < n; ++v) first[v + 1] += first[v];
    at.resize(first[n]);
    std::vector<std::uint32_t> next(first.begin(), first.end() - 1);
    for (const Subsegment& s : mesh.subsegments)
      if (s.a < n && s.b < n && s.a != s.b) at[next[s.a]++] = s.b, at[next[s.b]++] = s.a;
  }
};

// Whether another subsegment leaves vertex j within kSharpJunctionDeg of the one from j to p.
bool sharp_junction(const Mesh& mesh, const SubsegmentNeighbours& nb, VertexId j, VertexId p) {
  const Point &pj = mesh.point(j), &pp = mesh.point(p);
  const double ux = pp.x - pj.x, uy = pp.y - pj.y;
  for (std::uint32_t k = nb.first[j]; k < nb.first[j + 1]; ++k) {
    if (nb.at[k] == p) continue;
    const Point& pb = mesh.point(nb.at[k]);
    const double wx = pb.x - pj.x, wy = pb.y - pj.y;
    if (std::atan2(std::fabs(ux * wy - uy * wx), ux * wx + uy * wy) < kSharpJunctionDeg * (M_PI / 180.0)) return true;
  }
  return false;
}

// Walks the chain of straight vertices from v towards w, collecting them; whether its end (the
// first vertex that is not straight) is a sharp junction. A closed loop has no end.
bool chain_ends_sharp(const Mesh& mesh, const SubsegmentNeighbours& nb, const std::vector<char>& straight, VertexId v,
                      VertexId w, std::vector<VertexId>& chain) {
  VertexId prev = v, cur = w;
  while (cur != v && straight[cur]) {
    chain.push_back(cur);
    const VertexId a = nb.at[nb.first[cur]], b = nb.at[nb.first[cur] + 1];
    const VertexId next = a == prev ? b : a;
    prev = cur, cur = next;
  }
  return cur != v && sharp_junction(mesh, nb, cur, prev);
}

// Keeps the straight vertices of the chains that end at a sharp junction, and drops the others.
void keep_chains_into_sharp_junctions(const Mesh& mesh, std::vector<char>& straight) {
  const SubsegmentNeighbours nb(mesh);
  std::vector<char> seen(straight.size(), 0);
  std::vector<VertexId> chain;
  for (VertexId v{0}; v < straight.size(); ++v) {
    if (!straight[v] || seen[v]) continue;
    chain.assign(1, v);
    const VertexId a = nb.at[nb.first[v]], b = nb.at[nb.first[v] + 1];
    const bool sharp_a = chain_ends_sharp(mesh, nb, straight, v, a, chain);
    const bool sharp_b = chain_ends_sharp(mesh, nb, straight, v, b, chain);
    for (VertexId c : chain) seen[c] = 1;
    if (!sharp_a && !sharp_b)
      for (VertexId c : chain) straight[c] = 2;  // dropped once every chain is walked
  }
  for (char& s : straight) s = s == 1;
}

}  // namespace

SegmentPieces::SegmentPieces(const Mesh& mesh, bool straight_chains, bool sharp_junctions_only) {
  std::vector<char> straight =
      straight_chains ? straight_chain_vertices(mesh) : std::vector<char>(mesh.vertex_count(), 0);
  if (straight_chains && sharp_junctions_only) keep_chains_into_sharp_junctions(mesh, straight);
  // A chain's ends, walked from a subsegment record through straight vertices; a vertex's two
  // records are found through the records at each vertex.
  const std::size_t n = mesh.vertex_count();
  std::vector<std::array<std::uint32_t, 2>> at(n, {UINT32_MAX, UINT32_MAX});
  const std::uint32_t records = static_cast<std::uint32_t>(mesh.subsegments.size());
  for (std::uint32_t r = 0; r < records; ++r) {
    const Subsegment& sub = mesh.subsegments[r];
    for (VertexId v : {sub.a, sub.b})
      if (v < n && straight[v]) at[v][at[v][0] == UINT32_MAX ? 0 : 1] = r;
  }
  of_subsegment.assign(records, {kNone, kNone});
  std::vector<char> done(records, 0);
  std::vector<std::uint64_t> keys;
  keys.reserve(records);
  std::vector<std::uint32_t> chain;
  for (std::uint32_t r = 0; r < records; ++r) {
    if (done[r]) continue;
    const Subsegment& sub = mesh.subsegments[r];
    chain.assign(1, r);
    done[r] = 1;
    PieceEnds ends{sub.a, sub.b};
    for (int side = 0; side < 2; ++side) ends[side] = walk_straight(mesh, straight, at, ends[side], r, done, chain);
    for (std::uint32_t c : chain) of_subsegment[c] = ends;
    keys.push_back(piece_key(ends[0], ends[1]));
  }
  for (VertexId v{0}; v < n; ++v) {
    if (!straight[v] || at[v][0] == UINT32_MAX) continue;
    const PieceEnds& piece = of_subsegment[at[v][0]];
    if (piece[0] != v && piece[1] != v) splits.push_back({v, piece});  // else a loop's end
  }
  set_initial(std::move(keys));
}

void SegmentPieces::set_initial(std::vector<std::uint64_t> keys) {
  std::sort(keys.begin(), keys.end());
  initial = std::make_shared<const std::vector<std::uint64_t>>(std::move(keys));
}

void SegmentPieces::record_split(const Mesh& mesh, VertexId v, const PieceEnds& piece) {
  if (!splits.empty() && splits.back().vertex >= v) throw std::logic_error("segment splits recorded out of order");
  splits.push_back({v, piece});
  of_subsegment.resize(mesh.subsegments.size(), piece);  // the new half's record
}

// The split vertices are distinct and increasing, so split i is at least i ids after the first and
// at least (n - 1 - i) before the last: v can only be at an index in [v's distance from the
// last, counted back from the end; its distance from the first]. Where nearly every vertex is a
// split (a thin strip, refined only along its sides) that range holds an entry or two, and the
// search touches no more; elsewhere it is never wider than the whole list.
const PieceEnds* SegmentPieces::piece_of(VertexId v) const {
  const std::size_t n = splits.size();
  if (n == 0 || v < splits.front().vertex || v > splits.back().vertex) return nullptr;
  const std::size_t after_first = v - splits.front().vertex, before_last = splits.back().vertex - v;
  // Where every vertex since the first split is a split (a strip's refinement), v's entry is the
  // last place it can be: one comparison in place of the search.
  if (after_first < n && splits[after_first].vertex == v) return &splits[after_first].piece;
  const auto lo = splits.begin() + static_cast<std::ptrdiff_t>(n - 1 - std::min(before_last, n - 1));
  const auto hi = splits.begin() + static_cast<std::ptrdiff_t>(std::min(after_first, n - 1) + 1);
  const auto at = std::lower_bound(lo, hi, v, [](const Split& s, VertexId u) { return s.vertex < u; });
  return at != hi && at->vertex == v ? &at->piece : nullptr;
}

VertexId SegmentPieces::end_shared_with(const PieceEnds& mine, VertexId c) const {
  if (const PieceEnds* p = piece_of(c)) return shared_end(mine, *p);
  if (c == mine[0] || c == mine[1]) return kNone;
  for (VertexId o : mine)
    if (is_initial_piece(o, c)) return o;
  return kNone;
}

std::uint64_t SegmentPieces::piece_key(VertexId a, VertexId b) {
  if (a > b) std::swap(a, b);
  return static_cast<std::uint64_t>(a) << 32 | b;
}

bool SegmentPieces::is_initial_piece(VertexId a, VertexId b) const {
  return initial && std::binary_search(initial->begin(), initial->end(), piece_key(a, b));
}

}  // namespace deltri
