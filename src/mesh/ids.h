// Identifiers of the triangulation. Everything is a 32-bit index into a flat array, so a mesh of
// four billion triangles is the limit and every link costs four bytes.
//
// Each kind of id is its own type (Id<Tag>): one 32-bit member, trivially copyable, free to pass
// and compare. An id is made from an integer only explicitly (VertexId{n}), and one kind never
// turns into another by itself: a triangle id given where a vertex id is expected does not
// compile, and neither do comparisons between kinds or VertexId{t} for a triangle t. The only ways
// across are the named functions below (edge_of, triangle_of, side_of, lnext, lprev). An id
// converts implicitly to std::uint32_t, so it indexes the flat arrays (points[v], corner[e])
// unchanged; arithmetic on that integer gives an integer again, never an id, and slot arithmetic
// like 3 * t + i belongs to this file and src/mesh/ (tests/mesh/topology_writers.sh greps for it).
#pragma once

#include <compare>
#include <concepts>
#include <cstdint>
#include <functional>

namespace deltri {

struct EdgeTag;
struct TriangleTag;

template <class Tag>
struct Id;

// "No such id": converts to an id of every kind (and to a plain std::uint32_t, for the few
// non-id indices that use the same marker), all with the value 0xFFFFFFFF.
struct NoneId {
  template <class Tag>
  constexpr operator Id<Tag>() const;  // NOLINT: kNone is meant to convert to every id kind
  constexpr operator std::uint32_t() const { return 0xFFFFFFFFu; }  // NOLINT: and to an index
};
inline constexpr NoneId kNone{};

template <class Tag>
struct Id {
  std::uint32_t value;

  Id() = default;  // uninitialised like an integer, so arrays of ids fill as cheaply
  constexpr explicit Id(std::uint32_t v) : value(v) {}
  template <class Other>
  Id(Id<Other>) = delete;  // VertexId{t} for a triangle t: use a named conversion

  // The index into the flat arrays.
  constexpr operator std::uint32_t() const { return value; }  // NOLINT: ids index arrays

  constexpr Id& operator++() {
    ++value;
    return *this;
  }
  constexpr Id operator++(int) { return Id{value++}; }
  constexpr Id& operator--() {
    --value;
    return *this;
  }

  friend constexpr bool operator==(Id a, Id b) { return a.value == b.value; }
  friend constexpr auto operator<=>(Id a, Id b) { return a.value <=> b.value; }
  friend constexpr bool operator==(Id a, NoneId) { return a.value == 0xFFFFFFFFu; }

  // An oriented edge (Id<EdgeTag>, EdgeRef) is the slot 3 * triangle + side: side i of a
  // triangle runs from its corner i to corner i+1 (mod 3), with the triangle on its left. Its
  // navigation within the triangle lives with it; across triangles it needs the mesh (Mesh::sym).
  constexpr Id<TriangleTag> triangle() const
    requires std::same_as<Tag, EdgeTag>;
  constexpr unsigned side() const
    requires std::same_as<Tag, EdgeTag>
  {
    return value % 3;
  }
  // The next and previous edge of the same triangle, counter-clockwise.
  constexpr Id lnext() const
    requires std::same_as<Tag, EdgeTag>
  {
    return Id{value % 3 == 2 ? value - 2 : value + 1};
  }
  constexpr Id lprev() const
    requires std::same_as<Tag, EdgeTag>
  {
    return Id{value % 3 == 0 ? value + 2 : value - 1};
  }
};

// Comparing ids of two kinds is a mistake, not a comparison of their integers.
template <class A, class B>
  requires(!std::same_as<A, B>)
bool operator==(Id<A>, Id<B>) = delete;
template <class A, class B>
  requires(!std::same_as<A, B>)
auto operator<=>(Id<A>, Id<B>) = delete;

template <class Tag>
constexpr NoneId::operator Id<Tag>() const {
  return Id<Tag>{0xFFFFFFFFu};
}

using VertexId = Id<struct VertexTag>;
using TriangleId = Id<TriangleTag>;
using EdgeRef = Id<EdgeTag>;
using SubsegmentId = Id<struct SubsegmentTag>;

// The vertex "at infinity" that ghost triangles use while a triangulation is being built.
inline constexpr VertexId kGhostVertex{0xFFFFFFFEu};

template <class Tag>
constexpr TriangleId Id<Tag>::triangle() const
  requires std::same_as<Tag, EdgeTag>
{
  return TriangleId{value / 3};
}

constexpr EdgeRef edge_of(TriangleId t, unsigned side) { return EdgeRef{3 * t.value + side}; }
constexpr TriangleId triangle_of(EdgeRef e) { return e.triangle(); }
constexpr unsigned side_of(EdgeRef e) { return e.side(); }
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
  constexpr Iterator end() const { return {EdgeRef{first.value + 3}}; }
};
constexpr TriangleEdges edges_of(TriangleId t) { return {edge_of(t, 0)}; }
constexpr EdgeRef lnext(EdgeRef e) { return e.lnext(); }
constexpr EdgeRef lprev(EdgeRef e) { return e.lprev(); }

}  // namespace deltri

template <class Tag>
struct std::hash<deltri::Id<Tag>> {
  std::size_t operator()(deltri::Id<Tag> id) const noexcept { return std::hash<std::uint32_t>{}(id.value); }
};
