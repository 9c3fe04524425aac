// The id types of mesh/ids.h: what converts and what must not compile, and the edge handle's
// navigation against the slot layout it encodes (side i of triangle t is slot 3t + i).
#include <concepts>
#include <cstdint>
#include <type_traits>

#include "harness/check.h"
#include "mesh/ids.h"

using namespace deltri;

namespace {

template <class A, class B>
concept EqualityComparable = requires(A a, B b) { a == b; };
template <class A, class B>
concept Ordered = requires(A a, B b) { a < b; };

// As cheap as the integers they replace.
static_assert(sizeof(VertexId) == 4 && sizeof(EdgeRef) == 4);
static_assert(std::is_trivially_copyable_v<VertexId> && std::is_trivially_copyable_v<EdgeRef>);
static_assert(std::is_standard_layout_v<TriangleId>);

// Made from an integer only explicitly; read as one implicitly (indexing).
static_assert(!std::is_convertible_v<std::uint32_t, VertexId>);
static_assert(std::is_constructible_v<VertexId, std::uint32_t>);
static_assert(std::is_convertible_v<VertexId, std::uint32_t>);

// One kind never becomes another, implicitly or by a cast, nor compares with it.
static_assert(!std::is_convertible_v<TriangleId, VertexId>);
static_assert(!std::is_constructible_v<VertexId, TriangleId>);
static_assert(!std::is_constructible_v<TriangleId, EdgeRef>);
static_assert(!std::is_constructible_v<EdgeRef, TriangleId>);
static_assert(!std::is_constructible_v<SubsegmentId, VertexId>);
static_assert(!EqualityComparable<VertexId, TriangleId>);
static_assert(!EqualityComparable<EdgeRef, TriangleId>);
static_assert(!Ordered<VertexId, SubsegmentId>);
static_assert(EqualityComparable<VertexId, VertexId> && Ordered<EdgeRef, EdgeRef>);

// kNone is every kind's "none", and the integer marker too.
constexpr VertexId kNoVertex = kNone;
constexpr TriangleId kNoTriangle = kNone;
constexpr EdgeRef kNoEdge = kNone;
static_assert(kNoVertex == kNone && kNoTriangle == kNone && kNoEdge.value == 0xFFFFFFFFu);
static_assert(std::uint32_t{kNone} == 0xFFFFFFFFu);
static_assert(kGhostVertex != kNone && kGhostVertex == VertexId{0xFFFFFFFEu});

// The named conversions, at compile time.
static_assert(edge_of(TriangleId{5}, 2).value == 17);
static_assert(triangle_of(EdgeRef{17}) == TriangleId{5} && side_of(EdgeRef{17}) == 2);

}  // namespace

TEST(edge_handle_navigation_matches_the_slot_layout) {
  for (std::uint32_t t = 0; t < 50; ++t) {
    const TriangleId tri{t};
    unsigned count = 0;
    for (const EdgeRef e : edges_of(tri)) {
      const unsigned i = count++;
      CHECK_EQ(e.value, 3 * t + i);
      CHECK(e == edge_of(tri, i));
      CHECK(e.triangle() == tri && triangle_of(e) == tri);
      CHECK_EQ(e.side(), i);
      CHECK(e.lnext() == edge_of(tri, (i + 1) % 3) && lnext(e) == e.lnext());
      CHECK(e.lprev() == edge_of(tri, (i + 2) % 3) && lprev(e) == e.lprev());
      CHECK(e.lnext().lprev() == e && e.lnext().lnext().lnext() == e);
    }
    CHECK_EQ(count, 3u);
  }
}
