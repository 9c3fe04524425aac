#include "refine/candidate_probe.h"

#include <algorithm>
#include <cmath>

#include "geometry/constructions.h"
#include "util/prefetch.h"

namespace deltri {

void CavityMarks::begin() {
  if (stamped_) {
    for (TriangleId t : spilled_) {
      const std::uint32_t mask = (std::uint32_t{1} << table_bits_) - 1;
      std::uint32_t i = cavity_slot(t, table_bits_);
      while (table_[i] != t) i = (i + 1) & mask;
      table_[i] = kNone;
    }
    spilled_.clear();
  }
  listed_ = 0;
  listed_bits_ = 0;
  count_ = 0;
  stamped_ = false;
  boundary_.clear();
  boundary_subsegments_.clear();
  inner_.clear();
}

void CavityMarks::insert_spilled(TriangleId t) {
  if (2 * (spilled_.size() + 1) > table_.size()) {
    table_bits_ = std::max(table_bits_ + 1, 8u);
    table_.assign(std::size_t{1} << table_bits_, kNone);
    for (TriangleId u : spilled_) {
      std::uint32_t i = cavity_slot(u, table_bits_);
      while (table_[i] != kNone) i = (i + 1) & ((std::uint32_t{1} << table_bits_) - 1);
      table_[i] = u;
    }
  }
  std::uint32_t i = cavity_slot(t, table_bits_);
  while (table_[i] != kNone) i = (i + 1) & ((std::uint32_t{1} << table_bits_) - 1);
  table_[i] = t;
  spilled_.push_back(t);
}

void CavityMarks::spill() {
  for (std::size_t i = 0; i < listed_; ++i) insert_spilled(list_[i]);
  stamped_ = true;
}

bool CavityMarks::mark(TriangleId t) {
  if (contains(t)) return false;
  add(t);
  return true;
}

void CavityMarks::add_spilled(TriangleId t) {
  if (!stamped_) spill();
  insert_spilled(t);
}

KnownCavity CavityMarks::marked() const {
  KnownCavity cavity;
  if (stamped_) {
    cavity.table = table_.data(), cavity.table_bits = table_bits_;
  } else {
    cavity.list = list_, cavity.count = listed_;
  }
  cavity.triangles = count_;
  cavity.boundary = boundary_, cavity.inner = inner_;
  return cavity;
}

namespace detail {
namespace {

// The side of T through which the ray from q towards c leaves: its origin on or right of the
// ray, its destination strictly left, and c strictly beyond it. kNone if no side qualifies
// (q itself outside T by rounding, or a ray grazing a vertex).
EdgeRef exit_side(const Mesh& mesh, Predicates& pred, TriangleId t, const Point& q, const Point& c,
                  const double (&o)[3]) {
  for (unsigned i = 0; i < 3; ++i) {
    if (o[i] >= 0) continue;
    const EdgeRef e = edge_of(t, i);
    if (pred.orient2d(q, c, mesh.point(mesh.org(e))) <= 0 &&
        pred.orient2d(q, c, mesh.point(mesh.dest(e))) > 0)
      return e;
  }
  for (unsigned i = 0; i < 3; ++i)  // visibility step: any side that c lies beyond
    if (o[i] < 0) return edge_of(t, i);
  return kNone;
}

}  // namespace

WalkResult walk_towards(const Mesh& mesh, Predicates& pred, TriangleId t, const Point& c) {
  WalkResult result;
  const auto [a, b, d] = mesh.corner_points(t);
  const Point q{(a.x + b.x + d.x) / 3.0, (a.y + b.y + d.y) / 3.0};
  const std::uint64_t limit = 2 * static_cast<std::uint64_t>(mesh.triangle_slots()) + 16;
  for (std::uint64_t step = 0; step < limit; ++step) {
    double o[3];
    int zeros = 0;
    for (unsigned i = 0; i < 3; ++i) {
      const EdgeRef e = edge_of(t, i);
      o[i] = pred.orient2d(mesh.point(mesh.org(e)), mesh.point(mesh.dest(e)), c);
      zeros += o[i] == 0;
    }
    if (o[0] >= 0 && o[1] >= 0 && o[2] >= 0) {
      result.container = edge_of(t, 0);
      result.on_vertex = zeros >= 2;
      result.on_edge = zeros == 1;
      return result;
    }
    const EdgeRef exit = exit_side(mesh, pred, t, q, c, o);
    if (mesh.link[exit] == kNone || (mesh.has_subsegments() && mesh.subseg.has(exit))) {
      result.blocker = exit;
      return result;
    }
    t = triangle_of(mesh.link[exit]);
  }
  result.on_vertex = true;  // gave up: treat c as unusable rather than guess
  return result;
}

// One edge e of a cavity triangle: the triangle across it joins the cavity if its circumcircle
// contains c; otherwise, or across a subsegment or the mesh's boundary, e is on the cavity's
// boundary. Returns whether it is.
inline bool cross_or_bound(const Mesh& mesh, Predicates& pred, EdgeRef e, const Point& c, CavityMarks& marks) {
  if (mesh.has_subsegments() && mesh.subseg.has(e)) {
    marks.boundary_subsegments().push_back(e);
    marks.boundary().push_back(e);
    return true;
  }
  const EdgeRef twin = mesh.link[e];
  if (twin == kNone) {
    marks.boundary().push_back(e);
    return true;
  }
  const TriangleId n = triangle_of(twin);
  if (marks.contains(n)) return false;  // an edge inside the cavity, seen from its other side
  prefetch(&mesh.link[edge_of(n, 0)]);  // needed when n joins the cavity
  if (mesh.has_subsegments()) prefetch(mesh.subseg.bits_at(edge_of(n, 0)));
  const auto [x, y, z] = mesh.corner_points(n);
  if (pred.incircle(x, y, z, c) > 0) {
    marks.add(n);
    marks.todo().push_back(n);
    return false;
  }
  marks.boundary().push_back(e);
  return true;
}

double cavity_of(const Mesh& mesh, Predicates& pred, std::span<const TriangleId> seeds,
                 const Point& c, CavityMarks& marks) {
  marks.begin();
  std::vector<TriangleId>& todo = marks.todo();
  todo.clear();
  for (TriangleId s : seeds)
    if (marks.mark(s)) todo.push_back(s);
  while (!todo.empty()) {
    const TriangleId t = todo.back();
    todo.pop_back();
    bool on_boundary = false;
    for (unsigned i = 0; i < 3; ++i) on_boundary |= cross_or_bound(mesh, pred, edge_of(t, i), c, marks);
    if (!on_boundary) marks.inner().push_back(t);
  }
  // The cavity's vertices are its boundary's: no vertex lies inside the union of the triangles
  // whose circumcircles contain c (the region is star-shaped from c).
  double nearest2 = HUGE_VAL;
  for (EdgeRef e : marks.boundary()) nearest2 = std::min(nearest2, squared_distance(c, mesh.point(mesh.org(e))));
  return nearest2;
}

}  // namespace detail

double split_insertion_radius(const Mesh& mesh, Predicates& pred, EdgeRef s, const Point& c,
                              CavityMarks& marks) {
  const TriangleId seeds[2] = {triangle_of(s), triangle_of(mesh.link[s])};
  const std::size_t count = mesh.link[s] == kNone ? 1 : 2;
  return std::sqrt(detail::cavity_of(mesh, pred, {seeds, count}, c, marks));
}

}  // namespace deltri
