// Meshes for the refinement tests and independent checks of a refined mesh: exact orientation and
// incircle tests, plain trigonometry for angles, sums for areas. Nothing here calls src/refine.
#pragma once

#include <cmath>
#include <map>
#include <numbers>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "delaunay/triangulate.h"
#include "geometry/predicates.h"
#include "harness/id_literals.h"
#include "mesh/mesh.h"
#include "refine/refine.h"

namespace refine_test {

using namespace deltri;

// Options asking for the angle bound theta and nothing else.
inline RefineOptions quality(double theta) {
  RefineOptions opt;
  opt.angle = AngleBound(theta);
  return opt;
}

// The Delaunay triangulation of `points` (all Input).
inline Mesh triangulated(const std::vector<Point>& points) {
  Mesh m;
  for (const Point& p : points) m.add_vertex(p, VertexKind::Input);
  delaunay_triangulate(m, DelaunayAlgorithm::DivideAndConquer, 1);
  m.enable_subsegments();
  return m;
}

// Puts a subsegment on the edge between vertices a and b (it must exist). Returns false if not.
inline bool mark_segment(Mesh& m, std::uint32_t a, std::uint32_t b, int marker = 0) {
  for (EdgeRef e{0}; e < m.corner.size(); ++e) {
    if (m.corner[e] == kNone || m.org(e) != a || m.dest(e) != b) continue;
    const SubsegmentId id = static_cast<SubsegmentId>(m.subsegments.size());
    m.subsegments.push_back({VertexId{a}, VertexId{b}, marker, id});
    m.set_subsegment(e, id);
    return true;
  }
  for (EdgeRef e{0}; e < m.corner.size(); ++e)
    if (m.corner[e] != kNone && m.org(e) == b && m.dest(e) == a) return mark_segment(m, b, a, marker);
  return false;
}

// Every boundary edge becomes a subsegment (a convex domain bounded by its hull).
inline void mark_boundary(Mesh& m, int marker = 1) {
  for (EdgeRef e{0}; e < m.corner.size(); ++e) {
    if (m.corner[e] == kNone || m.link[e] != kNone || m.subseg.has(e)) continue;
    const SubsegmentId id = static_cast<SubsegmentId>(m.subsegments.size());
    m.subsegments.push_back({m.org(e), m.dest(e), marker, id});
    m.set_subsegment(e, id);
  }
}

inline Mesh unit_square() {
  Mesh m = triangulated({{0, 0}, {1, 0}, {1, 1}, {0, 1}});
  mark_boundary(m);
  return m;
}

inline double area_of(const Mesh& m, TriangleId t) {
  const Point& a = m.point(m.corner[edge_of(t, 0)]);
  const Point& b = m.point(m.corner[edge_of(t, 1)]);
  const Point& c = m.point(m.corner[edge_of(t, 2)]);
  return 0.5 * ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
}

// The angle at org(e) in degrees, by acos of the normalised dot product.
inline double angle_deg(const Mesh& m, EdgeRef e) {
  const Point& o = m.point(m.org(e));
  const Point& d = m.point(m.dest(e));
  const Point& a = m.point(m.apex(e));
  const double ux = d.x - o.x, uy = d.y - o.y, vx = a.x - o.x, vy = a.y - o.y;
  const double c = (ux * vx + uy * vy) / (std::hypot(ux, uy) * std::hypot(vx, vy));
  return std::acos(std::max(-1.0, std::min(1.0, c))) * 180.0 / std::numbers::pi;
}

inline double min_angle_deg(const Mesh& m, TriangleId t) {
  return std::min({angle_deg(m, edge_of(t, 0)), angle_deg(m, edge_of(t, 1)), angle_deg(m, edge_of(t, 2))});
}

struct Facts {
  std::size_t triangles = 0;
  bool all_ccw = true;
  bool links_ok = true;
  bool subsegments_symmetric = true;
  bool boundary_protected = true;       // every boundary edge carries a subsegment
  std::size_t non_delaunay_edges = 0;   // non-subsegment edges failing the exact incircle test
  double total_area = 0.0;
  double max_area = 0.0;
  double min_angle = 180.0;
  double boundary_length = 0.0;         // total length of boundary subsegments
};

inline Facts facts_of(const Mesh& m) {
  Predicates pred;
  Facts f;
  for (TriangleId t{0}; t < m.triangle_slots(); ++t) {
    if (!m.is_live(t)) continue;
    ++f.triangles;
    const Point& a = m.point(m.corner[edge_of(t, 0)]);
    const Point& b = m.point(m.corner[edge_of(t, 1)]);
    const Point& c = m.point(m.corner[edge_of(t, 2)]);
    if (!(pred.orient2d(a, b, c) > 0)) f.all_ccw = false;
    const double area = area_of(m, t);
    f.total_area += area;
    f.max_area = std::max(f.max_area, area);
    f.min_angle = std::min(f.min_angle, min_angle_deg(m, t));
    for (unsigned i = 0; i < 3; ++i) {
      const EdgeRef e = edge_of(t, i);
      const EdgeRef twin = m.link[e];
      const bool segment = !m.subseg.empty() && m.subseg.has(e);
      if (twin == kNone) {
        if (!segment) f.boundary_protected = false;
        else f.boundary_length += std::hypot(m.point(m.dest(e)).x - m.point(m.org(e)).x,
                                             m.point(m.dest(e)).y - m.point(m.org(e)).y);
        continue;
      }
      if (m.link[twin] != e || m.org(twin) != m.dest(e) || m.dest(twin) != m.org(e)) f.links_ok = false;
      if (!m.subseg.empty() && m.subseg[twin] != m.subseg[e]) f.subsegments_symmetric = false;
      if (!segment && pred.incircle(a, b, c, m.point(m.apex(twin))) > 0) ++f.non_delaunay_edges;
    }
  }
  return f;
}

// The triangles whose smallest angle is below `theta`.
inline std::vector<TriangleId> skinny_triangles(const Mesh& m, double theta) {
  std::vector<TriangleId> out;
  for (TriangleId t{0}; t < m.triangle_slots(); ++t)
    if (m.is_live(t) && min_angle_deg(m, t) < theta) out.push_back(t);
  return out;
}

// A bit-for-bit copy of the topology, for "nothing changed" checks.
struct Snapshot {
  BigVector<Point> points;
  BigVector<VertexId> corner;
  BigVector<EdgeRef> link;
  std::vector<SubsegmentId> subseg;
  std::size_t subsegments = 0;
  explicit Snapshot(const Mesh& m)
      : points(m.points), corner(m.corner.begin(), m.corner.end()), link(m.link.begin(), m.link.end()),
        subseg(m.subseg.dense()),
        subsegments(m.subsegments.size()) {}
  bool operator==(const Snapshot&) const = default;
};

}  // namespace refine_test
