#include "surface/surface_mesher.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <map>
#include <set>
#include <span>
#include <string>
#include <unordered_map>
#include <utility>

#include "geometry/collinear3.h"
#include "geometry/predicates.h"
#include "refine/termination_guard.h"
#include "util/errors.h"
#include "util/run_both.h"

namespace deltri {
namespace {

// Two recorded parameters closer than this (as a fraction of the segment) are one point: the
// facets compute the same split in different plane coordinates, equal only to rounding.
constexpr double kSameParameter = 1e-10;

struct Segment3 {
  std::uint32_t a = 0, b = 0;        // input point ids, a < b
  std::vector<std::uint32_t> facets;  // facets holding it, ascending
  std::vector<double> splits;         // parameters in (0, 1), ascending, where it is cut
  bool shared() const { return facets.size() >= 2; }
};

// Where a facet's PSLG vertex comes from: an input point, split `k` of segment `g`, or (neither)
// a seed from the facet's previous mesh.
struct LocalVertex {
  std::uint32_t input = kNone;
  std::uint32_t g = kNone;
  std::uint32_t k = 0;
};

// A PSLG segment of a facet: the part [ta, tb] of input segment g, between PSLG vertices la, lb.
struct Piece {
  std::uint32_t g = 0;
  double ta = 0.0, tb = 1.0;
  std::uint32_t la = 0, lb = 0;
};

struct FacetState {
  std::vector<std::uint32_t> segments;  // input segments it holds, ascending
  std::size_t own_steiner = 0;          // its mesh's Steiner points not on a shared segment
  std::vector<std::uint32_t> lone;      // lone vertices (one-corner polygons)
  std::vector<LocalVertex> local;       // per PSLG vertex
  std::vector<Piece> pieces;            // per PSLG segment
  FacetMeshResult result;
};

class SurfaceBuilder {
 public:
  SurfaceBuilder(const FacetInput& input, const FacetMeshOptions& options, int max_rounds, const SurfaceProgress& progress)
      : in_(input), options_(options), max_rounds_(max_rounds), progress_(progress) {}

  SurfaceMesh run(SurfaceReport& report);

 private:
  void collect_segments();
  void run_rounds(SurfaceReport& report, long& budget, bool give_up_on_stall);
  std::size_t shared_split_count() const;
  std::uint32_t segment_of(std::uint32_t a, std::uint32_t b);
  Pslg facet_pslg(std::uint32_t f);
  std::vector<std::pair<std::uint32_t, double>> new_cuts(std::uint32_t f) const;
  void refuse_foreign_vertex(std::uint32_t f) const;
  void refuse_lost_pieces(std::uint32_t f, const std::vector<char>& has_edge) const;
  void refuse_crossing(std::uint32_t f, std::uint32_t g, std::uint32_t h) const;
  void refuse_inside(std::uint32_t f, const LocalVertex& v, std::uint32_t g) const;
  void refuse_repeated_facets() const;
  void refuse_overlapping_segments() const;
  void refuse_points_inside_segments() const;
  [[noreturn]] void refuse(std::uint32_t f, const std::string& what) const;
  std::string name(std::uint32_t g) const { return id(segments_[g].a) + "-" + id(segments_[g].b); }
  std::string id(std::uint32_t i) const { return std::to_string(i + static_cast<std::uint32_t>(in_.first_index)); }
  bool holds_without(std::uint32_t other, const LocalVertex& v) const;
  bool add_splits_near(std::uint32_t g, double t, std::set<double>& splits) const;
  std::vector<std::uint32_t> mesh_facets(const std::vector<std::uint32_t>& facets, const FacetMeshOptions& options,
                                         bool record = true);
  std::vector<std::uint32_t> facet_vertices(std::uint32_t f, const std::vector<std::uint32_t>& split_base,
                                            SurfaceMesh& out) const;
  SurfaceMesh lift();
  std::size_t steiner_count() const;
  FacetMeshOptions share_of_budget(const FacetMeshOptions& options, std::size_t facets, long budget) const;

  const FacetInput& in_;
  const FacetMeshOptions& options_;
  const int max_rounds_;
  const SurfaceProgress& progress_;
  bool use_seeds_ = true;  // seed each facet with the interior vertices of its previous mesh
  bool one_tree_ = false;  // the second try's rules (run)
  std::vector<FacetPlane> planes_;
  std::vector<Segment3> segments_;
  std::unordered_map<std::uint64_t, std::uint32_t> segment_index_;
  std::vector<FacetState> facets_;
  std::vector<char> acute_;  // by input point: a corner under 60 degrees in some facet
};

std::uint32_t SurfaceBuilder::segment_of(std::uint32_t a, std::uint32_t b) {
  if (a > b) std::swap(a, b);
  const std::uint64_t key = (std::uint64_t{a} << 32) | b;
  const auto [it, added] = segment_index_.emplace(key, static_cast<std::uint32_t>(segments_.size()));
  if (added) segments_.push_back({a, b, {}, {}});
  return it->second;
}

// Every polygon edge of every facet becomes an input segment, identified by its two points, so
// that facets naming the same two points share it.
void SurfaceBuilder::collect_segments() {
  facets_.resize(in_.facets.size());
  acute_.assign(in_.points.size(), 0);
  for (std::uint32_t f = 0; f < in_.facets.size(); ++f) {
    FacetState& state = facets_[f];
    for (const auto& polygon : in_.facets[f].polygons) {
      if (polygon.size() == 1) state.lone.push_back(polygon[0]);
      const std::size_t edges = polygon.size() == 2 ? 1 : polygon.size() >= 3 ? polygon.size() : 0;
      for (std::size_t i = 0; i < edges; ++i) {
        const std::uint32_t a = polygon[i], b = polygon[(i + 1) % polygon.size()];
        if (a != b) state.segments.push_back(segment_of(a, b));
      }
    }
    for (const auto& polygon : in_.facets[f].polygons)
      for (std::size_t i = 0; polygon.size() >= 3 && i < polygon.size(); ++i) {
        const Point3 o = in_.points[polygon[i]];
        const Point3 u = in_.points[polygon[(i + 1) % polygon.size()]] - o;
        const Point3 w = in_.points[polygon[(i + polygon.size() - 1) % polygon.size()]] - o;
        // Under 60 degrees: cos > 1/2.
        if (2.0 * dot(u, w) > norm(u) * norm(w)) acute_[polygon[i]] = 1;
      }
    std::sort(state.segments.begin(), state.segments.end());
    state.segments.erase(std::unique(state.segments.begin(), state.segments.end()), state.segments.end());
    for (std::uint32_t g : state.segments) segments_[g].facets.push_back(f);
  }
}

// The interior vertices of the facet's previous mesh (its seeds and the free vertices refinement
// added), to seed the next: the facet is then re-meshed from nearly the mesh it had, and only the
// neighbourhood of new cuts changes. Empty before the first round.
std::vector<Point> previous_interior(const FacetState& state) {
  std::vector<Point> seeds;
  const Mesh& previous = state.result.mesh;
  for (std::uint32_t v = 0; v < previous.vertex_count(); ++v) {
    const bool seed = v < state.local.size() && state.local[v].input == kNone && state.local[v].g == kNone;
    if (seed || (v >= state.local.size() && previous.kind[v] == VertexKind::Free)) seeds.push_back(previous.points[v]);
  }
  return seeds;
}

// The facet in its plane coordinates: its points, each segment cut at the recorded splits, holes.
Pslg SurfaceBuilder::facet_pslg(std::uint32_t f) {
  FacetState& state = facets_[f];
  const FacetPlane& plane = planes_[f];
  Pslg pslg;
  const std::vector<Point> seeds = use_seeds_ ? previous_interior(state) : std::vector<Point>{};
  state.local.clear();
  state.pieces.clear();
  std::unordered_map<std::uint32_t, std::uint32_t> of_input;
  const auto input_vertex = [&](std::uint32_t v) {
    const auto [it, added] = of_input.emplace(v, static_cast<std::uint32_t>(state.local.size()));
    if (added) {
      state.local.push_back({v, kNone, 0});
      pslg.points.push_back(plane.to_plane(in_.points[v]));
    }
    return it->second;
  };
  for (std::uint32_t v : state.lone) input_vertex(v);
  for (const Point& p : seeds) {
    state.local.push_back({kNone, kNone, 0});
    pslg.points.push_back(p);
  }
  for (std::uint32_t g : state.segments) {
    const Segment3& s = segments_[g];
    const Point3 a = in_.points[s.a], d = in_.points[s.b] - a;
    std::uint32_t prev = input_vertex(s.a);
    double t_prev = 0.0;
    for (std::uint32_t k = 0; k <= s.splits.size(); ++k) {
      std::uint32_t next;
      double t;
      if (k == s.splits.size()) {
        next = input_vertex(s.b), t = 1.0;
      } else {
        t = s.splits[k];
        next = static_cast<std::uint32_t>(state.local.size());
        state.local.push_back({kNone, g, k});
        pslg.points.push_back(plane.to_plane(a + t * d));
      }
      state.pieces.push_back({g, t_prev, t, prev, next});
      pslg.segments.push_back({prev, next, 0});
      prev = next, t_prev = t;
    }
  }
  for (const Point3& h : in_.facets[f].holes) pslg.holes.push_back(plane.to_plane(h));
  return pslg;
}

// The vertices facet f's new mesh put inside its shared segments' pieces, as (segment,
// parameter) pairs.
std::vector<std::pair<std::uint32_t, double>> SurfaceBuilder::new_cuts(std::uint32_t f) const {
  const FacetState& state = facets_[f];
  const Mesh& mesh = state.result.mesh;
  const std::uint32_t n_local = static_cast<std::uint32_t>(state.local.size());
  std::vector<std::pair<std::uint32_t, double>> cuts;
  for (EdgeRef e{0}; e < mesh.corner.size(); ++e) {
    if (!mesh.has_subsegments() || !mesh.subseg.has(e) || mesh.corner[e] < n_local) continue;
    const Subsegment& rec = mesh.subsegments[mesh.subseg[e]];
    if (rec.segment >= state.pieces.size()) continue;
    const Piece& piece = state.pieces[rec.segment];
    if (!segments_[piece.g].shared()) continue;
    // Where the new vertex lies along its piece, as a parameter of the whole segment.
    const Point& p = mesh.points[mesh.corner[e]];
    const Point& a = mesh.points[piece.la];
    const Point& b = mesh.points[piece.lb];
    const double dx = b.x - a.x, dy = b.y - a.y;
    const double s = ((p.x - a.x) * dx + (p.y - a.y) * dy) / (dx * dx + dy * dy);
    cuts.emplace_back(piece.g, piece.ta + std::clamp(s, 0.0, 1.0) * (piece.tb - piece.ta));
  }
  return cuts;
}

// Whether facet `other` lacks vertex v (an input point or a split of a segment) that another
// facet found on a segment they share.
bool SurfaceBuilder::holds_without(std::uint32_t other, const LocalVertex& v) const {
  if (v.input != kNone) {
    for (const auto& polygon : in_.facets[other].polygons)
      if (std::find(polygon.begin(), polygon.end(), v.input) != polygon.end()) return false;
    return true;
  }
  const std::vector<std::uint32_t>& held = facets_[other].segments;
  return v.g == kNone || !std::binary_search(held.begin(), held.end(), v.g);
}

// Two facets with the same corners cover one piece of surface twice: each meshes it with Steiner
// points of its own, two vertices at one point, a surface cracked between them. Refused as a
// facet meeting another other than at whole segments and corners.
void SurfaceBuilder::refuse_repeated_facets() const {
  std::map<std::vector<std::uint32_t>, std::uint32_t> first;
  for (std::uint32_t f = 0; f < in_.facets.size(); ++f) {
    std::vector<std::uint32_t> corners;
    for (const auto& polygon : in_.facets[f].polygons) corners.insert(corners.end(), polygon.begin(), polygon.end());
    std::sort(corners.begin(), corners.end());
    corners.erase(std::unique(corners.begin(), corners.end()), corners.end());
    if (corners.size() < 3) continue;
    const auto [it, added] = first.emplace(std::move(corners), f);
    if (!added) refuse(f, "it has the corners of facet " + id(it->second) + ", one piece of surface twice");
  }
}

// Two segments from one point along one ray overlap: the shorter one's far end lies inside the
// longer, and a facet holding the longer one alone splits it there only if a split of its own
// happens to land on that point (the midpoint of a segment twice as long did: two vertices at one
// point, a cracked surface). Refused unless one facet holds both and no other holds either (its
// 2-D repair then merges them, as for a PSLG). Exact: collinear in all three coordinate planes.
void SurfaceBuilder::refuse_overlapping_segments() const {
  std::vector<std::vector<std::uint32_t>> at(in_.points.size());
  for (std::uint32_t g = 0; g < segments_.size(); ++g) at[segments_[g].a].push_back(g), at[segments_[g].b].push_back(g);
  Predicates pred;
  const auto far_end = [&](std::uint32_t g, std::uint32_t v) { return segments_[g].a == v ? segments_[g].b : segments_[g].a; };
  for (std::uint32_t v = 0; v < at.size(); ++v)
    for (std::size_t i = 0; i < at[v].size(); ++i)
      for (std::size_t j = i + 1; j < at[v].size(); ++j) {
        const Segment3 &s = segments_[at[v][i]], &t = segments_[at[v][j]];
        if (s.facets == t.facets && s.facets.size() == 1) continue;
        const Point3 o = in_.points[v], a = in_.points[far_end(at[v][i], v)], b = in_.points[far_end(at[v][j], v)];
        if (collinear3(pred, o, a, b) && dot(a - o, b - o) > 0.0)
          refuse(t.facets.front(), "its segment " + name(at[v][j]) + " overlaps segment " + name(at[v][i]) + " of facet " +
                                       id(s.facets.front()));
      }
}

double coordinate(const Point3& p, int axis) { return axis == 0 ? p.x : axis == 1 ? p.y : p.z; }

// Point p's coordinates starting at the axis, in cyclic order: ordered so, the points of a box
// are those between its two extreme corners, and where the box is flat in the leading axes (a
// segment parallel to a coordinate axis) nearly no others are.
std::array<double, 3> cyclic(const Point3& p, int axis) {
  return {coordinate(p, axis), coordinate(p, (axis + 1) % 3), coordinate(p, (axis + 2) % 3)};
}

// Facets' corners in the three cyclic orders, to find those in a segment's bounding box without
// a pass over all of them (a flat grid of 40,000 quads: 2 of 40,401 corners per segment).
class CornersByAxis {
 public:
  struct Corner {
    std::array<double, 3> key;
    std::uint32_t v;
  };
  CornersByAxis(const std::vector<Point3>& points, const std::vector<std::uint32_t>& facet_of) {
    for (int k = 0; k < 3; ++k) {
      for (std::uint32_t v = 0; v < facet_of.size(); ++v)
        if (facet_of[v] != kNone) sorted_[k].push_back({cyclic(points[v], k), v});
      std::sort(sorted_[k].begin(), sorted_[k].end(), [](const Corner& a, const Corner& b) { return a.key < b.key; });
    }
  }
  // A run of corners holding every corner in the box of p-q: the shortest of the three orders'.
  std::span<const Corner> candidates(const Point3& p, const Point3& q) const {
    const Point3 lo{std::min(p.x, q.x), std::min(p.y, q.y), std::min(p.z, q.z)};
    const Point3 hi{std::max(p.x, q.x), std::max(p.y, q.y), std::max(p.z, q.z)};
    std::span<const Corner> best;
    for (int k = 0; k < 3; ++k) {
      const std::array<double, 3> from = cyclic(lo, k), to = cyclic(hi, k);
      const auto below = [&](const Corner& c) { return c.key < from; };
      const auto first = std::partition_point(sorted_[k].begin(), sorted_[k].end(), below);
      const auto last = std::partition_point(first, sorted_[k].end(), [&](const Corner& c) { return c.key <= to; });
      if (k == 0 || last - first < static_cast<std::ptrdiff_t>(best.size())) best = {first, last};
    }
    return best;
  }

 private:
  std::array<std::vector<Corner>, 3> sorted_;
};

// Point v strictly inside segment p-q, exactly at any scale: within its bounding box (comparisons
// only), at neither end, and collinear with it.
bool strictly_inside(Predicates& pred, const Point3& v, const Point3& p, const Point3& q) {
  if (v == p || v == q) return false;
  for (int k = 0; k < 3; ++k)
    if (coordinate(v, k) < std::min(coordinate(p, k), coordinate(q, k)) ||
        coordinate(v, k) > std::max(coordinate(p, k), coordinate(q, k)))
      return false;
  return collinear3(pred, p, q, v);
}

// A corner of one facet strictly inside a segment that another facet holds without that corner:
// the facets then meet at a point inside an edge, which no facet's mesh makes a vertex unless a
// split lands on it exactly (a -a bound splitting the segment at its midpoint did: two vertices at
// one point, a cracked surface, exit 5; without a split, a T-junction -C cannot see, exit 0).
// Refused before meshing as refuse_inside refuses it after. A corner on a segment of its own
// facet that every facet holding the segment has too is legal: each facet's 2-D repair splits
// the segment there.
void SurfaceBuilder::refuse_points_inside_segments() const {
  std::vector<std::uint32_t> facet_of(in_.points.size(), kNone);  // the first facet with the corner
  for (std::uint32_t f = 0; f < in_.facets.size(); ++f)
    for (const auto& polygon : in_.facets[f].polygons)
      for (std::uint32_t v : polygon)
        if (facet_of[v] == kNone) facet_of[v] = f;
  const CornersByAxis corners(in_.points, facet_of);
  Predicates pred;
  for (std::uint32_t g = 0; g < segments_.size(); ++g) {
    const Point3 &p = in_.points[segments_[g].a], &q = in_.points[segments_[g].b];
    for (const CornersByAxis::Corner& c : corners.candidates(p, q))
      if (strictly_inside(pred, in_.points[c.v], p, q))
        refuse_inside(facet_of[c.v], LocalVertex{c.v, kNone, 0}, g);
  }
}

// The one-line refusal of an input whose facets cannot agree on a segment (refuse_foreign_vertex).
[[noreturn]] void SurfaceBuilder::refuse(std::uint32_t f, const std::string& what) const {
  throw InputError(in_.source_name, in_.facets[f].line,
                   "facet " + id(f) + ": " + what + " (facets may meet only at whole segments and corners)");
}

// Facet f's mesh has a vertex inside a piece of a shared segment that no facet can make agree:
// an input point of f on the segment, a split of another segment overlapping it (f's 2-D repair
// splits the piece there, but a facet holding the segment without that vertex never does), or a
// crossing of a shared segment with another segment (a cut of each: two vertices at one point, or
// a piece the other facets cannot follow; a cracked surface). Such an input is not a complex, and it is refused as
// the facet readers refuse other invalid facets.
void SurfaceBuilder::refuse_foreign_vertex(std::uint32_t f) const {
  const FacetState& state = facets_[f];
  const Mesh& mesh = state.result.mesh;
  if (!mesh.has_subsegments()) return;
  std::unordered_map<std::uint32_t, std::uint32_t> crossing;  // new vertex -> a segment it cuts
  std::vector<char> has_edge(state.pieces.size(), 0);
  // Both ends of each subsegment: a boundary subsegment has one half-edge, whose origin may be the
  // piece's own end.
  for (EdgeRef e{0}; e < mesh.corner.size(); ++e) {
    if (!mesh.subseg.has(e)) continue;
    const Subsegment& rec = mesh.subsegments[mesh.subseg[e]];
    if (rec.segment >= state.pieces.size()) continue;
    const Piece& piece = state.pieces[rec.segment];
    has_edge[rec.segment] = 1;
    for (const std::uint32_t v : {mesh.org(e), mesh.dest(e)}) {
      if (v >= state.local.size()) {
        const auto [it, added] = crossing.emplace(v, piece.g);
        if (!added && it->second != piece.g) refuse_crossing(f, it->second, piece.g);
      } else if (mesh.points[v] != mesh.points[piece.la] && mesh.points[v] != mesh.points[piece.lb]) {
        refuse_inside(f, state.local[v], piece.g);  // not the piece's end, nor a copy of it
      }
    }
  }
  refuse_lost_pieces(f, has_edge);
}

// A piece of a shared segment with no subsegment of its own in facet f's mesh: in the plane it
// merged with another of f's segments that overlaps it (or lies in a hole), so the other facets'
// edges along it would meet no edge of f. A safety net behind the planarity test (fuzz finding
// F13: a facet's points far off its plane projected onto one line).
void SurfaceBuilder::refuse_lost_pieces(std::uint32_t f, const std::vector<char>& has_edge) const {
  const FacetState& state = facets_[f];
  const Mesh& mesh = state.result.mesh;
  for (std::size_t p = 0; p < state.pieces.size(); ++p) {
    const Piece& piece = state.pieces[p];
    if (has_edge[p] || !segments_[piece.g].shared() || mesh.points[piece.la] == mesh.points[piece.lb]) continue;
    for (std::uint32_t other : segments_[piece.g].facets)
      if (other != f)
        refuse(f, "its segment " + name(piece.g) + ", an edge of facet " + id(other) +
                      " too, is no edge of its mesh (in its plane it overlaps another of its segments or lies in a hole)");
  }
}

// Two segments of facet f cross at a vertex its mesh made: refused where either is shared.
void SurfaceBuilder::refuse_crossing(std::uint32_t f, std::uint32_t g, std::uint32_t h) const {
  if (!segments_[g].shared() && !segments_[h].shared()) return;
  refuse(f, "its segments " + name(g) + " and " + name(h) + " cross, and " + name(segments_[h].shared() ? h : g) +
                " is an edge of another facet too");
}

// Vertex v of facet f's PSLG lies inside segment g: refused where a facet holds g without v.
void SurfaceBuilder::refuse_inside(std::uint32_t f, const LocalVertex& v, std::uint32_t g) const {
  for (std::uint32_t other : segments_[g].facets)
    if (other != f && holds_without(other, v))
      refuse(f, (v.input != kNone ? "point " + id(v.input)
                 : v.g != kNone   ? "a point of segment " + name(v.g)
                                  : std::string("a vertex")) +
                    " lies inside segment " + name(g) + ", which facet " + id(other) + " holds without it");
}

// The power of two in (d/3, 2d/3]: a concentric shell's radius (Sec. 6) for a piece of length d
// at a corner. Rounded down by 1e-9 so that lengths equal but for rounding pick the same shell.
double shell_radius_in_space(double d) {
  int e = 0;
  std::frexp(d * (2.0 / 3.0) * (1.0 - 1e-9), &e);
  return std::ldexp(1.0, e - 1);
}

// The one point where piece [u, v] of a segment (parameters, the segment `length` long) is split,
// whichever facet asks: the midpoint, or on a concentric shell around the segment's end where the
// piece has one at a corner under 60 degrees in some facet (as the 2-D Terminator's apices). Splits
// chosen so form one binary tree per segment, so two facets' splits
// never interleave: the pieces near a corner are the same shells in every facet around it.
double tree_split(double u, double v, double length, bool shells_at_a, bool shells_at_b) {
  if (u == 0.0 && shells_at_a && !(v == 1.0 && shells_at_b)) return shell_radius_in_space(v * length) / length;
  if (v == 1.0 && shells_at_b && !(u == 0.0 && shells_at_a)) return 1.0 - shell_radius_in_space((1.0 - u) * length) / length;
  return 0.5 * (u + v);
}

// A facet's mesh has a vertex at parameter t of segment g. The first try takes t as a split. The
// second (one_tree_) splits the piece holding t by the tree's rule, and the part of it that holds t
// again, until a split lies within a quarter of the piece of t: each facet's own split points
// (midpoints, shells, mirrored across thin wedges, measured in its own plane) interleaved with the
// others' and cut the pieces near small corners down to 1e-10 (the gear at -pq30a2). False when t
// is (within kSameParameter) a split or an end already: nothing was added.
bool SurfaceBuilder::add_splits_near(std::uint32_t g, double t, std::set<double>& splits) const {
  const Segment3& s = segments_[g];
  if (!one_tree_) {
    const auto at = splits.lower_bound(t);
    const bool near_next = at != splits.end() && *at - t < kSameParameter;
    const bool near_prev = at != splits.begin() && t - *std::prev(at) < kSameParameter;
    if (near_next || near_prev || t < kSameParameter || t > 1.0 - kSameParameter) return false;
    splits.insert(at, t);
    return true;
  }
  const double length = norm(in_.points[s.b] - in_.points[s.a]);
  bool added = false;
  for (;;) {
    const auto at = splits.lower_bound(t);
    const double u = at == splits.begin() ? 0.0 : *std::prev(at), v = at == splits.end() ? 1.0 : *at;
    if (t - u < kSameParameter || v - t < kSameParameter) return added;
    const double m = tree_split(u, v, length, acute_[s.a] != 0, acute_[s.b] != 0);
    if (!(m - u >= kSameParameter && v - m >= kSameParameter)) return added;
    splits.insert(m);
    added = true;
    if (std::abs(t - m) <= 0.25 * (v - u)) return added;
  }
}

// Meshes the given facets (on two threads with options.threads > 1: facets share nothing while
// they are meshed, and the cuts are merged afterwards in facet order, so the result does not
// depend on the threads); with `record`, adds the cuts to the segments' splits and returns the
// facets to mesh again: those holding a segment that gained a split, and those whose own cut was
// not taken. (The guard's last pass records nothing: the facets' vertex maps
// must keep naming the splits as they were built.)
std::vector<std::uint32_t> SurfaceBuilder::mesh_facets(const std::vector<std::uint32_t>& facets,
                                                       const FacetMeshOptions& options, bool record) {
  std::vector<std::vector<std::pair<std::uint32_t, double>>> cuts(facets.size());
  const auto mesh_every_other = [&](std::size_t first) {
    for (std::size_t i = first; i < facets.size(); i += 2) {
      FacetState& state = facets_[facets[i]];
      state.result = mesh_facet(facet_pslg(facets[i]), options);
      if (record) cuts[i] = new_cuts(facets[i]);
      // Its seeds and the vertices its refinement added, less those on shared segments (they
      // become splits, counted once for all the facets holding them).
      const Mesh& mesh = state.result.mesh;
      std::size_t own = 0;
      for (std::uint32_t v = 0; v < mesh.vertex_count(); ++v) {
        if (v < state.local.size())
          own += state.local[v].input == kNone && state.local[v].g == kNone;
        else
          own += mesh.kind[v] != VertexKind::Dead && mesh.kind[v] != VertexKind::Duplicate;
      }
      state.own_steiner = own - std::min(own, new_cuts(facets[i]).size());
    }
  };
  if (options.threads > 1 && facets.size() > 1)
    run_both([&] { mesh_every_other(1); }, [&] { mesh_every_other(0); });
  else
    for (std::size_t first : {0, 1}) mesh_every_other(first);
  for (std::uint32_t f : facets) refuse_foreign_vertex(f);
  // A facet whose cut another facet's split (or a segment's end) stood in for has a vertex of its
  // own on the segment where the others have none: it is meshed again on the splits as they are.
  // Declaring the surface converged with such a facet left subsegments that are no edge of it.
  // The cuts are merged into ordered sets, not the sorted vectors: one round can bring a segment
  // hundreds of thousands of cuts (fuzz_surface's finding F4 with its point at x = -4000, -pq30:
  // the first round ran for minutes inserting them into a vector one by one).
  std::unordered_map<std::uint32_t, std::set<double>> merging;
  std::vector<std::uint32_t> again;
  for (std::size_t i = 0; i < facets.size(); ++i)
    for (const auto& [g, t] : cuts[i]) {
      auto [at, fresh] = merging.try_emplace(g);
      if (fresh) at->second.insert(segments_[g].splits.begin(), segments_[g].splits.end());
      if (!add_splits_near(g, t, at->second)) {
        again.push_back(facets[i]);
        continue;
      }
      again.insert(again.end(), segments_[g].facets.begin(), segments_[g].facets.end());
    }
  for (const auto& [g, splits] : merging) segments_[g].splits.assign(splits.begin(), splits.end());
  std::sort(again.begin(), again.end());
  again.erase(std::unique(again.begin(), again.end()), again.end());
  return again;
}

// The Steiner points of the surface as the facets' meshes stand: each facet's own, and the
// splits of the segments.
std::size_t SurfaceBuilder::steiner_count() const {
  std::size_t n = 0;
  for (const FacetState& state : facets_) n += state.own_steiner;
  for (const Segment3& s : segments_) n += s.splits.size();
  return n;
}

// The options for one round's facets under -S: each facet may add an equal share of what is left.
// Equal shares keep the result independent of the order and the threads the facets are meshed
// on, and the round's facets together never exceed -S. Under the guard's budget alone each facet
// keeps its own 2-D guard, and the rounds end once the surface holds the budget's points: the run
// then holds at most the budget and one round's worth of facet caps.
FacetMeshOptions SurfaceBuilder::share_of_budget(const FacetMeshOptions& options, std::size_t facets, long budget) const {
  FacetMeshOptions o = options;
  if (budget < 0 || options.steiner_total < 0) return o;
  budget = std::min(budget, options.steiner_total);
  const std::size_t used = steiner_count();
  const long left = used >= static_cast<std::size_t>(budget) ? 0 : budget - static_cast<long>(used);
  o.refinement.max_steiner = left / static_cast<long>(std::max<std::size_t>(1, facets));
  return o;
}

std::size_t SurfaceBuilder::shared_split_count() const {
  std::size_t n = 0;
  for (const Segment3& s : segments_) n += s.shared() ? s.splits.size() : 0;
  return n;
}

// Facets that chase each other's cuts round after round: in the last kStallWindow rounds no
// fewer facets were left to mesh again than before them, and the shared segments gained at least
// as many splits as in the kStallWindow rounds before. Rounds that converge shed facets or add
// fewer splits from round to round. Seen in the first try only (run): the pynastran gear at
// -pq30a20 (22 facets again in every round from round 20 on, 45 to 71 splits each; the second try
// agrees after 19 rounds) and a facet point moved far out of its box (fuzz_surface's finding F4 at
// x = 4000: 3 facets, 4,594 more splits every two rounds, 160,000 Steiner points by round 40).
constexpr std::size_t kStallWindow = 4;

struct RoundState {
  std::size_t dirty = 0;
  std::size_t shared_splits = 0;
};

bool stalled(const std::vector<RoundState>& history) {
  const std::size_t n = history.size();
  if (n < 2 * kStallWindow + 1) return false;
  const RoundState &a = history[n - 1 - 2 * kStallWindow], &b = history[n - 1 - kStallWindow], &c = history[n - 1];
  for (std::size_t k = n - kStallWindow; k < n; ++k)
    if (history[k].dirty < b.dirty) return false;
  return c.shared_splits - b.shared_splits >= b.shared_splits - a.shared_splits;
}

// Rounds until the facets agree, the round cap, the budget, or (give_up_on_stall) a stall.
void SurfaceBuilder::run_rounds(SurfaceReport& report, long& budget, bool give_up_on_stall) {
  std::vector<RoundState> history;
  std::vector<std::uint32_t> dirty(facets_.size());
  for (std::uint32_t f = 0; f < dirty.size(); ++f) dirty[f] = f;
  report.converged = false;
  FacetMeshOptions options = options_;
  options.refinement.straight_chains = one_tree_;
  for (report.rounds = 1; report.rounds <= max_rounds_; ++report.rounds) {
    report.facet_meshings += dirty.size();
    const FacetMeshOptions round_options = share_of_budget(options, dirty.size(), budget);
    const std::vector<std::uint32_t> meshed = dirty;
    dirty = mesh_facets(dirty, round_options);
    for (std::uint32_t f : meshed)
      report.budget_reached = report.budget_reached || (budget >= 0 && facets_[f].result.refine.stopped_by_max_steiner);
    if (report.rounds == 1 && options_.refine) {
      double guard_total = 0.0;
      for (const FacetState& state : facets_) guard_total += static_cast<double>(state.result.refine.steiner_cap);
      if (const double memory = memory_budget_of(options_.refinement); memory > 0.0)
        guard_total = std::min(guard_total, memory / kBytesPerSteiner);
      const long guard = static_cast<long>(std::min(guard_total, 1e18));
      budget = budget < 0 ? guard : std::min(budget, guard);
    }
    history.push_back({dirty.size(), shared_split_count()});
    if (progress_) progress_({report.rounds, meshed.size(), steiner_count(), budget, history.back().shared_splits, dirty.size()});
    if (dirty.empty()) {
      report.converged = true;
      break;
    }
    if (give_up_on_stall && stalled(history)) break;
    // A facet stopped by its share would be meshed again with its old vertices and the others'
    // new cuts and nothing to spend on them: slivers. The last pass below does better.
    if (budget >= 0 && steiner_count() >= static_cast<std::size_t>(budget)) report.budget_reached = true;
    if (report.budget_reached) break;
  }
}

SurfaceMesh SurfaceBuilder::run(SurfaceReport& report) {
  for (std::size_t f = 0; f < in_.facets.size(); ++f) planes_.push_back(fit_facet_plane(in_, f));
  refuse_repeated_facets();
  collect_segments();
  refuse_overlapping_segments();
  refuse_points_inside_segments();
  // The rounds after the first re-mesh facets whose input grew by other facets' cuts, and their
  // 2-D guards, tied to that input, do not bound the whole run: one budget does (SurfaceReport).
  long budget = options_.refine ? options_.steiner_total : -1;
  run_rounds(report, budget, true);
  if (!report.converged && !report.budget_reached) {
    // The second try, from scratch: every facet splits a shared segment at the points of one tree
    // (add_splits_near), and takes other facets' cuts as splits of the straight chain they lie on
    // (as for -r), so a corner's pieces keep the corner as their end, its shells are measured
    // from it and the triangles between equal shells are spared as in one 2-D run. Each facet's
    // own split points near small corners interleaved with the others' and were cut down to
    // 1e-10 (the pynastran gear at -pq30a20, a2, a0.02: now 19, 13 and 29 rounds). Not the first
    // try: sparing the rung between unequal shells left 7.25 degrees at the wedge's 15.
    one_tree_ = true;
    for (Segment3& s : segments_) s.splits.clear();
    for (FacetState& state : facets_) state = FacetState{state.segments, 0, state.lone, {}, {}, {}};
    run_rounds(report, budget, false);
  }
  report.steiner_budget = budget;
  if (!report.converged) {
    // The guard: mesh every facet again with its segments kept as they are now, so that no facet
    // adds a cut and they all agree (under -S, a share of what it leaves). After the round cap the
    // seeds stay (the facets' meshes were near done: the pynastran gear at -pq30a0.02 misses -q
    // in 207 triangles with them, in 1,448 and -a in 1,017 without); after the budget they go, as
    // the seeds of a facet stopped mid-way crowd the cuts that reached it later (the 312-facet
    // sphere at -pq34: 915 misses of 171,760 without, 2,996 of 615,616 with).
    report.rounds = std::min(report.rounds, max_rounds_);
    use_seeds_ = !report.budget_reached;
    if (!use_seeds_)
      for (FacetState& state : facets_) state.own_steiner = 0;
    FacetMeshOptions kept = share_of_budget(options_, facets_.size(), budget);
    kept.refinement.no_steiner_on_segments = 2;
    std::vector<std::uint32_t> dirty(facets_.size());
    for (std::uint32_t f = 0; f < dirty.size(); ++f) dirty[f] = f;
    report.facet_meshings += dirty.size();
    mesh_facets(dirty, kept, false);
    for (const FacetState& state : facets_)
      report.budget_reached = report.budget_reached || (budget >= 0 && state.result.refine.stopped_by_max_steiner);
  }
  report.steiner_total = steiner_count();
  for (std::uint32_t f = 0; f < facets_.size(); ++f)
    if (!in_.facets[f].holes.empty() && facets_[f].result.mesh.live_triangles() == 0) report.emptied_facets.push_back(f);
  report.segments = segments_.size();
  for (const Segment3& s : segments_)
    if (s.shared()) ++report.shared_segments, report.shared_splits += s.splits.size();
  for (const FacetState& state : facets_) {
    add_counts(report.refine, state.result.refine);
    report.segment_repairs.crossings += state.result.segments.crossings;
    report.segment_repairs.snapped += state.result.segments.snapped;
  }
  return lift();
}

// Each vertex of facet f's mesh as a vertex of `out`: input points and cuts by their ids (cuts of
// segment g from split_base[g] on), the facet's seeds and new vertices lifted from its plane.
std::vector<std::uint32_t> SurfaceBuilder::facet_vertices(std::uint32_t f, const std::vector<std::uint32_t>& split_base,
                                                          SurfaceMesh& out) const {
  const FacetState& state = facets_[f];
  const Mesh& mesh = state.result.mesh;
  std::vector<std::uint32_t> global(mesh.vertex_count(), kNone);
  for (std::uint32_t v = 0; v < mesh.vertex_count(); ++v) {
    const LocalVertex* lv = v < state.local.size() ? &state.local[v] : nullptr;
    if (lv && lv->input != kNone) {
      global[v] = lv->input;
    } else if (lv && lv->g != kNone) {
      global[v] = split_base[lv->g] + lv->k;
    } else if (mesh.kind[v] != VertexKind::Dead && mesh.kind[v] != VertexKind::Duplicate) {
      global[v] = static_cast<std::uint32_t>(out.points.size());
      out.points.push_back(planes_[f].lift(mesh.points[v]));
    }
  }
  return global;
}

// Every facet's triangles in space, on one set of vertices.
SurfaceMesh SurfaceBuilder::lift() {
  SurfaceMesh out;
  out.points = in_.points;
  out.has_markers = in_.has_markers;
  out.markers = in_.markers;
  std::vector<std::uint32_t> split_base(segments_.size());
  for (std::uint32_t g = 0; g < segments_.size(); ++g) {
    const Segment3& s = segments_[g];
    split_base[g] = static_cast<std::uint32_t>(out.points.size());
    const Point3 a = in_.points[s.a], d = in_.points[s.b] - a;
    for (double t : s.splits) out.points.push_back(a + t * d);
  }
  std::unordered_map<std::uint64_t, std::uint32_t> edge_seen;
  for (std::uint32_t f = 0; f < facets_.size(); ++f) {
    std::vector<std::uint32_t> global = facet_vertices(f, split_base, out);
    FacetState& state = facets_[f];
    Mesh& mesh = state.result.mesh;
    for (TriangleId t{0}; t < mesh.triangle_slots(); ++t) {
      const auto [a, b, c] = mesh.corners(t);
      out.triangles.push_back({global[a], global[b], global[c]});
      out.triangle_facet.push_back(f);
    }
    for (EdgeRef e{0}; e < mesh.corner.size(); ++e) {
      if (!mesh.has_subsegments() || !mesh.subseg.has(e)) continue;
      const std::uint32_t a = global[mesh.org(e)], b = global[mesh.dest(e)];
      const std::uint64_t key = (std::uint64_t{std::min(a, b)} << 32) | std::max(a, b);
      const Subsegment& rec = mesh.subsegments[mesh.subseg[e]];
      if (rec.segment < state.pieces.size() && edge_seen.emplace(key, 0).second)
        out.subsegments.push_back({a, b, state.pieces[rec.segment].g});
    }
    out.facet_vertex.push_back(std::move(global));
    out.facet_meshes.push_back(std::move(mesh));
    out.facet_marker.push_back(in_.facets[f].marker);
  }
  if (out.has_markers) out.markers.resize(out.points.size(), 0);
  out.planes = planes_;
  for (const Segment3& s : segments_) out.segment_facets.push_back(s.facets);
  return out;
}

}  // namespace

SurfaceMesh mesh_surface(const FacetInput& input, const FacetMeshOptions& options, SurfaceReport& report,
                         int max_rounds, const SurfaceProgress& progress) {
  SurfaceBuilder builder(input, options, max_rounds, progress);
  return builder.run(report);
}

}  // namespace deltri
