// Identifiers of the triangulation. Everything is a 32-bit index into a flat array, so a mesh of
// four billion triangles is the limit and every link costs four bytes.
#pragma once

#include <cstdint>

namespace deltri {

using VertexId = std::uint32_t;
using TriangleId = std::uint32_t;
// An oriented edge: 3 * triangle + side. Side i of a triangle runs from its corner i to corner
// i+1 (mod 3), with the triangle on its left.
using EdgeRef = std::uint32_t;
using SubsegmentId = std::uint32_t;

inline constexpr std::uint32_t kNone = 0xFFFFFFFFu;
// The vertex "at infinity" that ghost triangles use while a triangulation is being built.
inline constexpr VertexId kGhostVertex = 0xFFFFFFFEu;

constexpr EdgeRef edge_of(TriangleId t, unsigned side) { return 3 * t + side; }
constexpr TriangleId triangle_of(EdgeRef e) { return e / 3; }
constexpr unsigned side_of(EdgeRef e) { return e % 3; }
// The three edges of triangle t, for `for (EdgeRef e : edges_of(t))`.
struct TriangleEdges {
  EdgeRef first;
  struct Iterator {
    EdgeRef e;
    constexpr EdgeRef operator*() const { return e; }
    constexpr Iterator& operator++() {
      ++e;
      return *this;
    }
    constexpr bool operator!=(Iterator other) const { return e != other.e; }
  };
  constexpr Iterator begin() const { return {first}; }
  constexpr Iterator end() const { return {first + 3}; }
};
constexpr TriangleEdges edges_of(TriangleId t) { return {3 * t}; }
// The next and previous edge of the same triangle, counter-clockwise.
constexpr EdgeRef lnext(EdgeRef e) { return e % 3 == 2 ? e - 2 : e + 1; }
constexpr EdgeRef lprev(EdgeRef e) { return e % 3 == 0 ? e + 2 : e - 1; }

}  // namespace deltri
