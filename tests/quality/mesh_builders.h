// Small meshes assembled by hand (add_triangle + bond), so that the checker and the statistics are
// judged against meshes whose every fact is known from the drawing, not from another algorithm.
#pragma once

#include <cstdint>
#include <unordered_map>
#include <vector>

#include "harness/id_literals.h"
#include "mesh/mesh.h"

namespace quality_test {

using namespace deltri;

inline Mesh mesh_of(const std::vector<Point>& points) {
  Mesh m;
  for (const Point& p : points) m.add_vertex(p, VertexKind::Input);
  return m;
}

// A flat diamond a=(-2,0), b=(0,-1), c=(2,0), d=(0,1) (vertices 0..3). The short diagonal b-d is
// Delaunay: the circle through a, b, d has centre (-3/4, 0) and radius 5/4, so c is outside. The
// long diagonal a-c is not: the circle through a, b, c has centre (0, 3/2) and radius 5/2, and d
// is inside.
inline Mesh diamond() { return mesh_of({{-2, 0}, {0, -1}, {2, 0}, {0, 1}}); }

// Triangles (a,b,d) = edges 0 a->b, 1 b->d, 2 d->a and (b,c,d) = edges 3 b->c, 4 c->d, 5 d->b.
inline Mesh diamond_short_diagonal() {
  Mesh m = diamond();
  m.add_triangle(0_v, 1_v, 3_v);
  m.add_triangle(1_v, 2_v, 3_v);
  m.bond(1_e, 5_e);
  return m;
}

// Triangles (a,b,c) = edges 0 a->b, 1 b->c, 2 c->a and (a,c,d) = edges 3 a->c, 4 c->d, 5 d->a.
inline Mesh diamond_long_diagonal() {
  Mesh m = diamond();
  m.add_triangle(0_v, 1_v, 2_v);
  m.add_triangle(0_v, 2_v, 3_v);
  m.bond(2_e, 3_e);
  return m;
}

// Bonds every pair of live edges with swapped endpoints.
inline void bond_all(Mesh& m) {
  const auto key = [](VertexId a, VertexId b) { return (std::uint64_t{a} << 32) | b; };
  std::unordered_map<std::uint64_t, EdgeRef> open;  // directed edge -> its unbonded slot
  for (EdgeRef e{0}; e < m.corner.size(); ++e) {
    if (!m.is_live(triangle_of(e))) continue;
    const auto twin = open.find(key(m.dest(e), m.org(e)));
    if (twin == open.end()) {
      open.emplace(key(m.org(e), m.dest(e)), e);
    } else {
      m.bond(e, twin->second);
      open.erase(twin);
    }
  }
}

// Centre 0 = (0,0) and ring 1..8 = the boundary of the square [-1,1]^2 counter-clockwise from
// (1,0). Triangle i (i = 0..7) is (centre, ring i+1, ring i+2); its edge 3i+1 lies on the ring.
// Every spoke is locally Delaunay, the diagonal spokes with four cocircular points (the corners of
// a unit square), which must count as Delaunay.
inline Mesh square_fan() {
  Mesh m = mesh_of({{0, 0}, {1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}});
  for (std::uint32_t i = 0; i < 8; ++i) m.add_triangle(0_v, VertexId{1 + i}, VertexId{1 + (i + 1) % 8});
  for (TriangleId i{0}; i < 8; ++i) m.bond(edge_of(i, 2), edge_of(TriangleId{(i + 1) % 8}, 0));
  return m;
}

// An n x n grid of unit squares, each cut by a diagonal alternating in a checkerboard; all four
// corners of every square are cocircular and the hull has collinear boundary vertices.
inline Mesh grid(unsigned n) {
  Mesh m;
  for (unsigned y = 0; y <= n; ++y)
    for (unsigned x = 0; x <= n; ++x) m.add_vertex({double(x), double(y)}, VertexKind::Input);
  for (unsigned y = 0; y < n; ++y) {
    for (unsigned x = 0; x < n; ++x) {
      const VertexId a{y * (n + 1) + x}, b{a + 1}, c{b + n + 1}, d{a + n + 1};
      if ((x + y) % 2 == 0) {
        m.add_triangle(a, b, c);
        m.add_triangle(a, c, d);
      } else {
        m.add_triangle(a, b, d);
        m.add_triangle(b, c, d);
      }
    }
  }
  bond_all(m);
  return m;
}

}  // namespace quality_test
