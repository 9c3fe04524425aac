// Shared helpers of the constrained Delaunay tests. Every fact is computed here from the mesh
// arrays with exact predicates, independently of the code under test.
#pragma once

#include <cmath>
#include <functional>
#include <map>
#include <set>
#include <vector>

#include "cdt/insert_segments.h"
#include "delaunay/triangulate.h"
#include "harness/check.h"
#include "harness/id_literals.h"

namespace cdt_test {

using namespace deltri;

struct Built {
  Mesh mesh;
  Predicates pred;
  DelaunayReport dt;
  SegmentReport seg;
};

inline void triangulate_and_insert(Built& b, const std::vector<Point>& points,
                                   const std::vector<Pslg::Segment>& segments) {
  b.mesh.points.assign(points.begin(), points.end());
  b.mesh.kind.assign(points.size(), VertexKind::Input);
  b.dt = delaunay_triangulate(b.mesh, DelaunayAlgorithm::DivideAndConquer, 1);
  b.seg = insert_segments(b.mesh, b.pred, segments, b.dt.duplicates);
}

// Every live triangle strictly counter-clockwise; links are involutions between reversed edges;
// both sides of an edge carry the same subsegment, whose record names the edge's ends.
inline bool mesh_valid(const Mesh& m) {
  Predicates p;
  for (TriangleId t{0}; t < m.triangle_slots(); ++t) {
    if (!m.is_live(t)) continue;
    const EdgeRef e = edge_of(t, 0);
    if (!(p.orient2d(m.point(m.corner[e]), m.point(m.corner[e + 1]), m.point(m.corner[e + 2])) > 0))
      return false;
    for (unsigned i = 0; i < 3; ++i) {
      const EdgeRef a = edge_of(t, i), b = m.link[a];
      if (b != kNone) {
        if (m.link[b] != a || m.org(b) != m.dest(a) || m.dest(b) != m.org(a)) return false;
        if (m.has_subsegments() && m.subseg[a] != m.subseg[b]) return false;
      }
      if (m.has_subsegments() && m.subseg.has(a)) {
        if (m.subseg[a] >= m.subsegments.size()) return false;
        const Subsegment& s = m.subsegments[m.subseg[a]];
        const bool same = (s.a == m.org(a) && s.b == m.dest(a)) || (s.b == m.org(a) && s.a == m.dest(a));
        if (!same) return false;
      }
    }
  }
  return true;
}

// Every interior edge without a subsegment is locally Delaunay.
inline bool constrained_delaunay(const Mesh& m) {
  Predicates p;
  for (EdgeRef e{0}; e < m.corner.size(); ++e) {
    if (m.corner[e] == kNone || m.link[e] == kNone) continue;
    if (m.has_subsegments() && m.subseg.has(e)) continue;
    if (p.incircle(m.point(m.org(e)), m.point(m.dest(e)), m.point(m.apex(e)),
                   m.point(m.apex(m.link[e]))) > 0)
      return false;
  }
  return true;
}

inline double area(const Mesh& m) {
  double total = 0;
  for (TriangleId t{0}; t < m.triangle_slots(); ++t) {
    if (!m.is_live(t)) continue;
    const Point &a = m.point(m.corner[edge_of(t, 0)]), &b = m.point(m.corner[edge_of(t, 1)]),
                &c = m.point(m.corner[edge_of(t, 2)]);
    total += 0.5 * ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
  }
  return total;
}

// Vertex adjacency along live edges that carry a subsegment accepted by `keep`.
inline std::map<VertexId, std::set<VertexId>> subsegment_graph(
    const Mesh& m, const std::function<bool(const Subsegment&)>& keep) {
  std::map<VertexId, std::set<VertexId>> g;
  for (EdgeRef e{0}; e < m.corner.size(); ++e) {
    if (m.corner[e] == kNone || !m.subseg.has(e)) continue;
    if (!keep(m.subsegments[m.subseg[e]])) continue;
    g[m.org(e)].insert(m.dest(e));
    g[m.dest(e)].insert(m.org(e));
  }
  return g;
}

// (Vertex numbers as plain integers in these helpers, so that tests can name vertices by literals.)
inline bool connected(const std::map<VertexId, std::set<VertexId>>& g, std::uint32_t from, std::uint32_t b) {
  const VertexId a{from};
  std::set<VertexId> seen{a};
  std::vector<VertexId> stack{a};
  while (!stack.empty()) {
    const VertexId v = stack.back();
    stack.pop_back();
    if (v == b) return true;
    const auto it = g.find(v);
    if (it == g.end()) continue;
    for (const VertexId w : it->second)
      if (seen.insert(w).second) stack.push_back(w);
  }
  return false;
}

// Input segment a-b is present as a chain of subsegment edges whose vertices all lie exactly on it.
inline bool collinear_chain(const Mesh& m, std::uint32_t a, std::uint32_t b) {
  Predicates p;
  const Point pa = m.point(VertexId{a}), pb = m.point(VertexId{b});
  const auto inside = [&](VertexId v) {
    const Point& q = m.point(v);
    return p.orient2d(pa, pb, q) == 0 && std::min(pa.x, pb.x) <= q.x && q.x <= std::max(pa.x, pb.x) &&
           std::min(pa.y, pb.y) <= q.y && q.y <= std::max(pa.y, pb.y);
  };
  return connected(subsegment_graph(m, [&](const Subsegment& s) { return inside(s.a) && inside(s.b); }),
                   a, b);
}

// Input segment `index` (ends a, b) is present as a chain of its own subsegment records.
inline bool chain_of_segment(const Mesh& m, std::uint32_t index, std::uint32_t a, std::uint32_t b) {
  return connected(subsegment_graph(m, [&](const Subsegment& s) { return s.segment == index; }), a, b);
}

inline std::size_t live_edges_with_subsegment(const Mesh& m) {
  std::size_t n = 0;
  for (EdgeRef e{0}; e < m.corner.size(); ++e)
    if (m.corner[e] != kNone && m.subseg.has(e) && (m.link[e] == kNone || m.link[e] > e)) ++n;
  return n;
}

// No live triangle contains q in its closed interior.
inline bool uncovered(const Mesh& m, const Point& q) {
  Predicates p;
  for (TriangleId t{0}; t < m.triangle_slots(); ++t) {
    if (!m.is_live(t)) continue;
    bool in = true;
    for (unsigned i = 0; i < 3; ++i)
      in = in && p.orient2d(m.point(m.corner[edge_of(t, i)]), m.point(m.corner[edge_of(t, (i + 1) % 3)]), q) >= 0;
    if (in) return false;
  }
  return true;
}

inline std::vector<Pslg::Segment> ring(std::uint32_t first, std::uint32_t count, int marker = 0) {
  std::vector<Pslg::Segment> s;
  for (std::uint32_t i = 0; i < count; ++i) s.push_back({first + i, first + (i + 1) % count, marker});
  return s;
}

}  // namespace cdt_test
