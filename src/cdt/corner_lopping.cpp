#include "cdt/corner_lopping.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <utility>

#include "mesh/subsegments.h"

namespace deltri {
namespace {

constexpr double kSmallAngle = std::numbers::pi / 3.0;  // 60 degrees
constexpr double kTurn = 2.0 * std::numbers::pi;

struct Spoke {  // a segment at an apex
  double direction;
  std::uint32_t segment;
};

// The segments at each vertex, counter-clockwise by direction (degenerate ones skipped).
std::vector<std::vector<Spoke>> segments_at(const Pslg& pslg, const Mesh& domain) {
  std::vector<std::vector<Spoke>> at(domain.points.size());
  for (std::uint32_t i = 0; i < pslg.segments.size(); ++i) {
    const auto [a, b, marker] = pslg.segments[i];
    if (a == b) continue;
    const Point& pa = domain.point(VertexId{a});
    const Point& pb = domain.point(VertexId{b});
    at[a].push_back({std::atan2(pb.y - pa.y, pb.x - pa.x), i});
    at[b].push_back({std::atan2(pa.y - pb.y, pa.x - pb.x), i});
  }
  for (auto& spokes : at)
    std::sort(spokes.begin(), spokes.end(), [](const Spoke& x, const Spoke& y) { return x.direction < y.direction; });
  return at;
}

// The sector of spokes that contains direction d: k spans spokes[k] to spokes[k + 1] counter-clockwise.
std::size_t sector_of(const std::vector<Spoke>& spokes, double d) {
  std::size_t k = spokes.size() - 1;
  for (std::size_t i = 0; i < spokes.size(); ++i)
    if (spokes[i].direction <= d) k = i;
  return k;
}

// Two spokes in the same direction (segments overlapping at the vertex, which the repair of the
// segments merges later) bound a sector of width 0, not a full turn: only a lone spoke has a turn
// around it. Counted as a turn, such a sector let the apex be lopped with a shield vertex on each
// of the overlapping segments, the same point twice, and the shields' repair was reported as
// duplicate vertices and repeated segments of the input.
double sector_width(const std::vector<Spoke>& spokes, std::size_t k) {
  const double w = spokes[(k + 1) % spokes.size()].direction - spokes[k].direction;
  if (w == 0.0 && spokes.size() >= 2) return 0.0;
  return w <= 0.0 ? w + kTurn : w;
}

// Which sectors at each vertex hold a triangle of the domain: read off the bisector of each
// triangle's angle there.
std::vector<std::vector<char>> inside_sectors(const Mesh& domain, const std::vector<std::vector<Spoke>>& at) {
  std::vector<std::vector<char>> inside(at.size());
  for (std::size_t v = 0; v < at.size(); ++v) inside[v].assign(at[v].size() >= 2 ? at[v].size() : 0, 0);
  for (TriangleId t{0}; t < domain.triangle_slots(); ++t) {
    if (!domain.is_live(t)) continue;
    const auto c = domain.corners(t);
    for (int i = 0; i < 3; ++i) {
      if (c[i] >= at.size() || inside[c[i]].empty()) continue;
      const Point& o = domain.point(c[i]);
      const Point& p = domain.point(c[(i + 1) % 3]);
      const Point& q = domain.point(c[(i + 2) % 3]);
      const double lp = std::hypot(p.x - o.x, p.y - o.y), lq = std::hypot(q.x - o.x, q.y - o.y);
      const double bx = (p.x - o.x) / lp + (q.x - o.x) / lq, by = (p.y - o.y) / lp + (q.y - o.y) / lq;
      inside[c[i]][sector_of(at[c[i]], std::atan2(by, bx))] = 1;
    }
  }
  return inside;
}

// A sector inside the domain under 60 degrees (60 to rounding is not small): its corner is lopped.
bool is_lopped_sector(const std::vector<Spoke>& spokes, const std::vector<char>& inside, std::size_t k) {
  return inside[k] && sector_width(spokes, k) < kSmallAngle * (1.0 - 1e-9);
}

// Whether a is lopped: it has a small sector inside the domain, and no segment between such a
// sector and a wider one inside (a vertex where the domain pinches, a segment hanging into it at a
// small angle). The paper cuts such a wider sector's arc into pieces of at most 60 degrees, but
// refinement splits those chords where they are encroached from outside, and the fan behind them
// then has thin triangles at a in an angle that is not small (water.poly: 8 degrees in a
// 359-degree sector); shielding the small sector alone leaves thin triangles beside its spoke,
// which cannot be split. Such an apex is left to refinement, as without the option. Segments
// overlapping at a (a sector of width 0 to rounding) would put two shield vertices at one place:
// such an apex is not lopped either.
bool to_be_lopped(const std::vector<Spoke>& spokes, const std::vector<char>& inside) {
  const std::size_t n = inside.size();
  bool small = false;
  for (std::size_t k = 0; k < n; ++k) {
    if (sector_width(spokes, k) < 1e-9) return false;
    if (!is_lopped_sector(spokes, inside, k)) continue;
    small = true;
    for (const std::size_t j : {(k + 1) % n, (k + n - 1) % n})
      if (inside[j] && !is_lopped_sector(spokes, inside, j)) return false;
  }
  return small;
}

double distance_to_segment(const Point& p, const Point& a, const Point& b) {
  const double dx = b.x - a.x, dy = b.y - a.y, l2 = dx * dx + dy * dy;
  const double t = l2 > 0.0 ? std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / l2, 0.0, 1.0) : 0.0;
  return std::hypot(a.x + t * dx - p.x, a.y + t * dy - p.y);
}

// lfs(a): the distance to the nearest other vertex or segment without a as an end (all of them
// looked at: lopping is for the small inputs the paper compares on).
double feature_size(const Pslg& pslg, const Mesh& domain, VertexId a) {
  double nearest = HUGE_VAL;
  const Point& pa = domain.point(a);
  for (VertexId v{0}; v < pslg.points.size(); ++v) {
    const Point& q = domain.point(v);
    if (v != a && domain.kind[v] == VertexKind::Input) nearest = std::min(nearest, std::hypot(q.x - pa.x, q.y - pa.y));
  }
  for (const Pslg::Segment& s : pslg.segments)
    if (s.a != a && s.b != a) nearest = std::min(nearest, distance_to_segment(pa, domain.point(VertexId{s.a}), domain.point(VertexId{s.b})));
  return nearest;
}

// Appends to the PSLG: points (with the apex's attributes), and segments flagged internal or not.
class Lopper {
 public:
  Lopper(Pslg& pslg, CornerLopping& out) : pslg_(pslg), out_(out), cut_(pslg.segments.size(), {kNone, kNone}) {
    out_.apex.assign(pslg.points.size(), 0);
    out_.internal.assign(pslg.segments.size(), 0);
  }
  void lop(VertexId a, double r, const std::vector<Spoke>& spokes, const std::vector<char>& inside);
  void split_cut_segments();

 private:
  VertexId add_point(const Point& p, int marker, VertexId like);
  void add_segment(VertexId a, VertexId b, int marker, bool internal) {
    pslg_.segments.push_back({a, b, marker});
    out_.internal.push_back(internal ? 1 : 0);
  }
  Pslg& pslg_;
  CornerLopping& out_;
  std::vector<std::array<VertexId, 2>> cut_;  // by original segment: the shield vertex near its a, near its b
};

VertexId Lopper::add_point(const Point& p, int marker, VertexId like) {
  const auto v = static_cast<VertexId>(pslg_.points.size());
  pslg_.points.push_back(p);
  const auto n = static_cast<std::size_t>(pslg_.num_attributes);
  for (std::size_t i = 0; i < n; ++i) pslg_.attributes.push_back(pslg_.attributes[like * n + i]);
  if (pslg_.has_markers) pslg_.markers.push_back(marker);
  out_.apex.push_back(kShieldVertex);
  return v;
}

// One apex: a shield vertex on each segment that bounds a small sector inside the domain (the
// segment's other side is outside or small too), and the chord across each such sector (under 60
// degrees: one arc; the fan is the triangle of a and the chord, more once the chord is split).
void Lopper::lop(VertexId a, double r, const std::vector<Spoke>& spokes, const std::vector<char>& inside) {
  const Point pa = pslg_.points[a];
  const std::size_t n = spokes.size();
  std::vector<VertexId> on_segment(n, kNone);
  for (std::size_t k = 0; k < n; ++k) {
    if (!is_lopped_sector(spokes, inside, k) && !is_lopped_sector(spokes, inside, (k + n - 1) % n)) continue;
    const Pslg::Segment seg = pslg_.segments[spokes[k].segment];
    on_segment[k] = add_point({pa.x + r * std::cos(spokes[k].direction), pa.y + r * std::sin(spokes[k].direction)}, seg.marker, a);
    cut_[spokes[k].segment][seg.a == a ? 0 : 1] = on_segment[k];
  }
  for (std::size_t k = 0; k < n; ++k) {
    if (!is_lopped_sector(spokes, inside, k)) continue;
    add_segment(on_segment[k], on_segment[(k + 1) % n], 0, true);  // the chord
    out_.sectors.push_back({a, on_segment[k], on_segment[(k + 1) % n]});
  }
  out_.apex[a] = kLoppedApex;
  ++out_.apices;
  out_.shortest_radius = out_.apices == 1 ? r : std::min(out_.shortest_radius, r);
}

// Each original segment a-b with shield vertices becomes a-s, s-t, t-b (the same marker): pieces
// of X's segment, not internal.
void Lopper::split_cut_segments() {
  for (std::size_t i = 0; i < cut_.size(); ++i) {
    const auto [near_a, near_b] = cut_[i];
    if (near_a == kNone && near_b == kNone) continue;
    const Pslg::Segment seg = pslg_.segments[i];
    VertexId chain[4];
    std::size_t n = 0;
    chain[n++] = VertexId{seg.a};
    if (near_a != kNone) chain[n++] = near_a;
    if (near_b != kNone) chain[n++] = near_b;
    chain[n++] = VertexId{seg.b};
    pslg_.segments[i].b = chain[1];
    for (std::size_t k = 1; k + 1 < n; ++k) add_segment(chain[k], chain[k + 1], seg.marker, false);
  }
}

}  // namespace

CornerLopping lop_corners(Pslg& pslg, const Mesh& domain) {
  const auto at = segments_at(pslg, domain);
  const auto inside = inside_sectors(domain, at);
  // Every radius first, from X alone: the shields added to the PSLG are no features of X.
  std::vector<std::pair<VertexId, double>> shields;
  for (VertexId v{0}; v < at.size(); ++v) {
    if (inside[v].empty() || !to_be_lopped(at[v], inside[v])) continue;
    const double r = feature_size(pslg, domain, v) / 3.0;
    if (r > 0.0 && std::isfinite(r)) shields.emplace_back(v, r);
  }
  CornerLopping out;
  Lopper lopper(pslg, out);
  for (const auto& [v, r] : shields) lopper.lop(v, r, at[v], inside[v]);
  lopper.split_cut_segments();
  return out;
}

void forget_lopping_edges(Mesh& mesh, const std::vector<char>& internal) {
  if (internal.empty() || !mesh.has_subsegments()) return;  // no corner lopped: the mesh stays as it is
  for (EdgeRef e{0}; e < mesh.subseg.size(); ++e) {
    const SubsegmentId s = mesh.subseg[e];
    if (s == kNone || !mesh.is_live(triangle_of(e))) continue;
    const std::uint32_t segment = mesh.subsegments[s].segment;
    if (segment < internal.size() && internal[segment]) unconstrain(mesh, e);
  }
  drop_dead_subsegments(mesh);
}

}  // namespace deltri
