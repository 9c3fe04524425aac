// Facts about a mesh computed independently of the code under test: orientation and circle tests
// by exact predicates, link consistency, Euler's formula, a monotone-chain hull. Used by the tests
// in this directory and by the refinement tests that compare insertions.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <map>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "geometry/predicates.h"
#include "harness/id_literals.h"
#include "mesh/mesh.h"

namespace meshcheck {

using namespace deltri;

inline Mesh mesh_of(const std::vector<Point>& pts) {
  Mesh m;
  m.points.assign(pts.begin(), pts.end());
  m.kind.assign(pts.size(), VertexKind::Input);
  return m;
}

// A mesh with the given counter-clockwise triangles (vertex numbers), twins found by matching
// reversed edges.
inline Mesh make_mesh(const std::vector<Point>& pts, const std::vector<std::array<std::uint32_t, 3>>& tris) {
  Mesh m = mesh_of(pts);
  std::map<std::pair<VertexId, VertexId>, EdgeRef> edges;
  for (const auto& t : tris) {
    const TriangleId id = m.add_triangle(VertexId{t[0]}, VertexId{t[1]}, VertexId{t[2]});
    for (unsigned i = 0; i < 3; ++i) {
      const EdgeRef e = edge_of(id, i);
      edges[{m.org(e), m.dest(e)}] = e;
      const auto twin = edges.find({m.dest(e), m.org(e)});
      if (twin != edges.end()) m.bond(e, twin->second);
    }
  }
  return m;
}

// Live triangles that are not strictly counter-clockwise or have an invalid corner.
inline int orientation_faults(const Mesh& m) {
  Predicates pred;
  int bad = 0;
  for (TriangleId t{0}; t < m.triangle_slots(); ++t) {
    if (!m.is_live(t)) continue;
    const VertexId a = m.corner[edge_of(t, 0)], b = m.corner[edge_of(t, 1)], c = m.corner[edge_of(t, 2)];
    if (a >= m.vertex_count() || b >= m.vertex_count() || c >= m.vertex_count()) { ++bad; continue; }
    if (pred.orient2d(m.point(a), m.point(b), m.point(c)) <= 0) ++bad;
  }
  return bad;
}

// Broken twins (not an involution, endpoints not swapped, dead partner) and subsegment mismatches.
inline int link_faults(const Mesh& m) {
  int bad = 0;
  if (m.link.size() != m.corner.size()) return 1;
  if (!m.subseg.empty() && m.subseg.size() != m.corner.size()) return 1;
  for (EdgeRef e{0}; e < m.corner.size(); ++e) {
    if (!m.is_live(triangle_of(e))) continue;
    const EdgeRef f = m.link[e];
    if (f == kNone) continue;
    if (f >= m.corner.size() || !m.is_live(triangle_of(f)) || m.link[f] != e) { ++bad; continue; }
    if (m.org(f) != m.dest(e) || m.dest(f) != m.org(e)) ++bad;
    if (!m.subseg.empty() && m.subseg[e] != m.subseg[f]) ++bad;
  }
  return bad;
}

// V - E + F over the live triangles (1 for a triangulated disk).
inline long euler_characteristic(const Mesh& m) {
  std::set<VertexId> verts;
  std::set<std::pair<VertexId, VertexId>> edges;
  long faces = 0;
  for (TriangleId t{0}; t < m.triangle_slots(); ++t) {
    if (!m.is_live(t)) continue;
    ++faces;
    for (unsigned i = 0; i < 3; ++i) {
      const EdgeRef e = edge_of(t, i);
      verts.insert(m.org(e));
      edges.insert(std::minmax(m.org(e), m.dest(e)));
    }
  }
  return static_cast<long>(verts.size()) - static_cast<long>(edges.size()) + faces;
}

// Interior edges without a subsegment whose opposite vertex lies strictly inside the circle.
inline int delaunay_faults(const Mesh& m) {
  Predicates pred;
  int bad = 0;
  for (EdgeRef e{0}; e < m.corner.size(); ++e) {
    if (!m.is_live(triangle_of(e)) || m.link[e] == kNone) continue;
    if (!m.subseg.empty() && m.subseg.has(e)) continue;
    const Point& a = m.point(m.org(e));
    const Point& b = m.point(m.dest(e));
    const Point& c = m.point(m.apex(e));
    if (pred.incircle(a, b, c, m.point(m.apex(m.link[e]))) > 0) ++bad;
  }
  return bad;
}

inline int all_faults(const Mesh& m) { return orientation_faults(m) + link_faults(m); }

using Triple = std::array<std::uint32_t, 3>;  // vertex numbers, for comparing with literals

// The live triangles as vertex triples rotated to start at their smallest id, sorted.
inline std::vector<Triple> triangle_set(const Mesh& m) {
  std::vector<Triple> s;
  for (TriangleId t{0}; t < m.triangle_slots(); ++t) {
    if (!m.is_live(t)) continue;
    Triple a{m.corner[edge_of(t, 0)], m.corner[edge_of(t, 1)], m.corner[edge_of(t, 2)]};
    std::rotate(a.begin(), std::min_element(a.begin(), a.end()), a.end());
    s.push_back(a);
  }
  std::sort(s.begin(), s.end());
  return s;
}

inline std::vector<Point> gaussian(std::size_t n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> g(0.0, 1.0);
  std::vector<Point> pts(n);
  for (Point& p : pts) p = {g(rng), g(rng)};
  return pts;
}

inline std::vector<Point> shuffled_grid(int w, int h, unsigned seed) {
  std::vector<Point> pts;
  for (int i = 0; i < w; ++i)
    for (int j = 0; j < h; ++j) pts.push_back({i * 0.25, j * 0.25});
  std::shuffle(pts.begin(), pts.end(), std::mt19937(seed));
  return pts;
}

// Distinct points on the convex hull boundary, corners and points on hull edges alike.
inline std::size_t hull_boundary_points(std::vector<Point> pts) {
  Predicates pred;
  std::sort(pts.begin(), pts.end(), [](const Point& a, const Point& b) {
    return a.x < b.x || (a.x == b.x && a.y < b.y);
  });
  pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
  std::vector<Point> hull;
  for (int pass = 0; pass < 2; ++pass) {
    const std::size_t start = hull.size();
    for (const Point& p : pts) {
      while (hull.size() >= start + 2 && pred.orient2d(hull[hull.size() - 2], hull.back(), p) <= 0)
        hull.pop_back();
      hull.push_back(p);
    }
    hull.pop_back();
    std::reverse(pts.begin(), pts.end());
  }
  std::size_t count = 0;
  for (const Point& p : pts)
    for (std::size_t i = 0; i < hull.size(); ++i) {
      const Point& a = hull[i];
      const Point& b = hull[(i + 1) % hull.size()];
      if (pred.orient2d(a, b, p) == 0 && std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) &&
          std::min(a.y, b.y) <= p.y && p.y <= std::max(a.y, b.y)) {
        ++count;
        break;
      }
    }
  return count;
}

inline std::vector<Point> uniform(std::size_t n, unsigned seed, double scale = 1.0, double offset = 0.0) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Point> p(n);
  for (auto& q : p) q = {offset + scale * u(rng), offset + scale * u(rng)};
  return p;
}

// The unit square as two triangles (0,0) (1,0) (1,1) (0,1), diagonal 0-2.
inline Mesh unit_square() {
  return make_mesh({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {{0, 1, 2}, {0, 2, 3}});
}

// The live edge from a to b (vertex numbers, so that tests can name them by literals), or kNone.
inline EdgeRef find_edge(const Mesh& m, std::uint32_t a, std::uint32_t b) {
  for (EdgeRef e{0}; e < m.corner.size(); ++e)
    if (m.is_live(triangle_of(e)) && m.org(e) == a && m.dest(e) == b) return e;
  return kNone;
}

}  // namespace meshcheck
