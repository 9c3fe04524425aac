// Mesh::subseg is sparse (mesh/subsegment_slots.h): a bit per slot and a hash table of the set
// slots' ids (a dense array of ids where a quarter of the slots carry one). These tests drive it through the kernel's writes with a plain dense array kept
// alongside as the reference, and check every slot, the count, the walk order and equality after
// each step: random sets and clears (many collisions in small tables, growth, backward-shift
// deletion), truncation, renumbering, and the mesh operations that move triangles (compaction).
#include <algorithm>
#include <random>
#include <vector>

#include "harness/check.h"
#include "harness/id_literals.h"
#include "mesh/subsegments.h"
#include "mesh/topology_writer.h"
#include "mesh_checks.h"

using namespace deltri;
using namespace meshcheck;

namespace {

// A mesh of n unlinked triangles (the slots are what matters here) with subsegments enabled.
Mesh slots_mesh(std::uint32_t triangles) {
  Mesh m = mesh_of({{0, 0}, {1, 0}, {0, 1}});
  for (std::uint32_t t = 0; t < triangles; ++t) m.append_triangle(0_v, 1_v, 2_v);
  m.enable_subsegments();
  return m;
}

// Every way of reading the slots agrees with the reference.
bool matches(const Mesh& m, const std::vector<SubsegmentId>& ref) {
  if (m.subseg.size() != ref.size()) return false;
  std::size_t set = 0;
  for (std::size_t e = 0; e < ref.size(); ++e) {
    if (m.subseg[e] != ref[e] || m.subseg.has(e) != (ref[e] != kNone)) return false;
    set += ref[e] != kNone;
  }
  if (m.subseg.count() != set) return false;
  std::vector<std::size_t> walked;
  bool same = true;
  m.subseg.for_each([&](EdgeRef e, SubsegmentId s) {
    walked.push_back(e);
    same = same && ref[e] == s;
  });
  return same && walked.size() == set && std::is_sorted(walked.begin(), walked.end()) &&
         m.subseg.dense() == ref;
}

// Sets every step-th slot from `first` on to id(e), in the mesh and in the reference.
template <class IdOf>
void set_every(Mesh& m, std::vector<SubsegmentId>& ref, std::size_t first, std::size_t step, IdOf id) {
  for (std::size_t e = first; e < ref.size(); e += step) {
    detail::subseg_slots(m).set(e, id(e));
    ref[e] = id(e);
  }
}

SubsegmentId id_of(std::size_t n) { return SubsegmentId{static_cast<std::uint32_t>(n)}; }

}  // namespace

TEST(random_sets_and_clears_match_a_dense_array) {
  std::mt19937 rng(7);
  for (std::uint32_t triangles : {1u, 5u, 40u, 3000u}) {
    Mesh m = slots_mesh(triangles);
    std::vector<SubsegmentId> ref(m.corner.size(), kNone);
    CHECK(matches(m, ref));
    const std::size_t slots = ref.size();
    std::size_t peak = 0;
    for (int step = 0; step < 20000; ++step) {
      const std::size_t e = rng() % slots;
      // Dense phases then sparse phases, so the table both grows and empties.
      const bool fill = (step / 2500) % 2 == 0;
      const SubsegmentId s = rng() % 4 < (fill ? 3u : 1u) ? SubsegmentId{static_cast<std::uint32_t>(rng() % 1000)}
                                                          : SubsegmentId{kNone};
      detail::subseg_slots(m).set(e, s);
      ref[e] = s;
      peak = std::max(peak, m.subseg.count());
      if (step % 97 == 0) CHECK(matches(m, ref));
    }
    CHECK(matches(m, ref));
    CHECK(peak > std::min<std::size_t>(slots / 2, 1500));  // the table was well filled at some point
  }
}

TEST(every_slot_set_then_cleared_in_turn) {
  Mesh m = slots_mesh(700);
  std::vector<SubsegmentId> ref(m.corner.size(), kNone);
  set_every(m, ref, 0, 1, id_of);
  CHECK(matches(m, ref));
  CHECK_EQ(m.subseg.count(), ref.size());
  const auto none = [](std::size_t) { return SubsegmentId{kNone}; };
  set_every(m, ref, 0, 2, none);
  CHECK(matches(m, ref));
  set_every(m, ref, 1, 2, none);
  CHECK(matches(m, ref));
  CHECK_EQ(m.subseg.count(), 0u);
}

// erase_all and set_all write a list of slots at once (fetching ahead in the table): the same
// contents as writing them one by one, in small tables where runs wrap past the end and in large
// ones.
TEST(erase_all_and_set_all_match_writing_one_by_one) {
  std::mt19937 rng(11);
  for (std::uint32_t triangles : {3u, 50u, 5000u}) {
    Mesh m = slots_mesh(triangles);
    std::vector<SubsegmentId> ref(m.corner.size(), kNone);
    for (std::size_t e = 0; e < ref.size(); ++e)
      if (rng() % 3 != 0) {
        detail::subseg_slots(m).set(e, id_of(e % 97));
        ref[e] = id_of(e % 97);
      }
    std::vector<EdgeRef> cleared;
    for (std::size_t e = 0; e < ref.size(); ++e)
      if (ref[e] != kNone && rng() % 2 == 0) {
        cleared.push_back(EdgeRef{static_cast<std::uint32_t>(e)});
        ref[e] = kNone;
      }
    std::shuffle(cleared.begin(), cleared.end(), rng);
    cleared.push_back(cleared.front());  // a slot already cleared is left alone
    detail::subseg_slots(m).erase_all(cleared);
    CHECK(matches(m, ref));
    CHECK(!cleared.empty());
    // set_all: new values on set and unset slots alike, a slot written twice keeping the later.
    std::vector<std::pair<EdgeRef, SubsegmentId>> values;
    for (std::size_t e = 0; e < ref.size(); ++e)
      if (rng() % 2 == 0) values.emplace_back(EdgeRef{static_cast<std::uint32_t>(e)}, id_of(1000 + e % 89));
    std::shuffle(values.begin(), values.end(), rng);
    values.emplace_back(values.front().first, id_of(7));
    for (const auto& [e, id] : values) ref[e] = id;
    detail::subseg_slots(m).set_all(values);
    CHECK(matches(m, ref));
  }
}

TEST(resize_drops_the_slots_past_the_end_and_appends_empty_ones) {
  Mesh m = slots_mesh(300);
  std::vector<SubsegmentId> ref(m.corner.size(), kNone);
  set_every(m, ref, 0, 3, [](std::size_t e) { return id_of(e % 17); });
  detail::subseg_slots(m).resize(100);
  ref.resize(100);
  CHECK(matches(m, ref));
  detail::subseg_slots(m).resize(500);
  ref.resize(500, kNone);
  CHECK(matches(m, ref));  // the slots dropped come back empty
  detail::subseg_slots(m).assign(64);
  CHECK(matches(m, std::vector<SubsegmentId>(64, kNone)));
}

TEST(remap_renumbers_and_clears) {
  Mesh m = slots_mesh(200);
  std::vector<SubsegmentId> ref(m.corner.size(), kNone);
  set_every(m, ref, 0, 2, [](std::size_t e) { return id_of(e % 10); });
  // Odd ids go, even ones are halved.
  const auto renumber = [](SubsegmentId s) { return s % 2 == 1 ? SubsegmentId{kNone} : SubsegmentId{s / 2}; };
  detail::subseg_slots(m).remap(renumber);
  for (SubsegmentId& s : ref)
    if (s != kNone) s = renumber(s);
  CHECK(matches(m, ref));
}

TEST(equality_is_by_contents_not_by_table_layout) {
  Mesh a = slots_mesh(100), b = slots_mesh(100);
  for (std::uint32_t e = 0; e < 300; e += 7) detail::subseg_slots(a).set(e, SubsegmentId{e});
  for (std::uint32_t e = 300; e-- > 0;)  // the same values written in the other order, with detours
    if (e % 7 == 0) {
      detail::subseg_slots(b).set(e, 5_s);
      detail::subseg_slots(b).set(e + 1, 5_s);
      detail::subseg_slots(b).set(e, SubsegmentId{e});
      detail::subseg_slots(b).set(e + 1, kNone);
    }
  CHECK(a.subseg == b.subseg);
  detail::subseg_slots(b).set(1, 1_s);
  CHECK(!(a.subseg == b.subseg));
}

// Compaction moves triangles over dead slots: each live triangle keeps its three subsegments,
// whichever slot it lands in, and the slots past the end are gone.
TEST(compaction_carries_each_triangles_subsegments) {
  std::mt19937 rng(11);
  Mesh m = mesh_of({{0, 0}, {1, 0}, {0, 1}});
  const std::uint32_t n = 2000;
  for (std::uint32_t t = 0; t < n; ++t) {
    m.add_vertex({2.0 + t, 0.0}, VertexKind::Input);  // vertex 3 + t names triangle t
    m.append_triangle(0_v, 1_v, VertexId{3 + t});
  }
  m.enable_subsegments();
  std::vector<std::array<SubsegmentId, 3>> by_vertex(n, {kNone, kNone, kNone});
  for (std::uint32_t t = 0; t < n; ++t)
    for (unsigned i = 0; i < 3; ++i)
      if (rng() % 3 == 0) {
        by_vertex[t][i] = SubsegmentId{static_cast<std::uint32_t>(rng() % 500)};
        detail::subseg_slots(m).set(edge_of(TriangleId{t}, i), by_vertex[t][i]);
      }
  std::vector<char> dead(n, 0);
  for (std::uint32_t t = 0; t < n; ++t)
    if (rng() % 2 == 0 || t >= n - 100) {  // the last ones too, so the end shrinks past them
      m.kill_triangle(TriangleId{t});
      dead[t] = 1;
    }
  const std::size_t live = static_cast<std::size_t>(std::count(dead.begin(), dead.end(), 0));
  m.compact_triangles();
  CHECK_EQ(m.triangle_slots(), live);
  CHECK_EQ(m.subseg.size(), m.corner.size());
  std::size_t expected = 0, seen = 0;
  for (std::uint32_t t = 0; t < n; ++t)
    if (!dead[t])
      for (SubsegmentId s : by_vertex[t]) expected += s != kNone;
  for (TriangleId t{0}; t < m.triangle_slots(); ++t) {
    const std::uint32_t original = m.corner[edge_of(t, 2)] - 3;
    CHECK(!dead[original]);
    for (unsigned i = 0; i < 3; ++i) {
      CHECK_EQ(m.subseg[edge_of(t, i)], by_vertex[original][i]);
      seen += m.subseg.has(edge_of(t, i));
    }
  }
  CHECK_EQ(seen, expected);
  CHECK_EQ(m.subseg.count(), expected);  // nothing left behind in the table
}

// The twin invariant through the kernel's own edits: set_subsegment writes both sides, unconstrain
// clears both.
TEST(set_subsegment_writes_the_edge_and_its_twin) {
  Mesh m = make_mesh({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {{0, 1, 2}, {0, 2, 3}});
  m.enable_subsegments();
  EdgeRef diagonal{kNone};
  for (EdgeRef e{0}; e < m.corner.size(); ++e)
    if (m.link[e] != kNone) diagonal = e;
  const SubsegmentId id = constrain(m, diagonal, {m.org(diagonal), m.dest(diagonal), 3, kNone});
  CHECK(m.subseg.has(diagonal) && m.subseg.has(m.link[diagonal]));
  CHECK_EQ(m.subseg[m.link[diagonal]], id);
  CHECK_EQ(m.subseg.count(), 2u);
  unconstrain(m, m.link[diagonal]);
  CHECK(!m.subseg.has(diagonal) && !m.subseg.has(m.link[diagonal]));
  CHECK_EQ(m.subseg.count(), 0u);
}

// A thin strip's mesh: every triangle appended carries a subsegment on its first side (a third of
// the slots). The hash table would hold 3,100 entries in 8,192 places of 8 bytes (21 bytes per
// subsegment); a value per slot is 12, plus the bits.
TEST(a_strip_where_every_triangle_carries_a_subsegment_costs_a_value_per_slot) {
  const std::uint32_t n = 3100;
  Mesh m = slots_mesh(1);
  m.reserve_triangles(n);
  std::vector<SubsegmentId> ref(m.corner.size(), kNone);
  for (std::uint32_t t = 1; t < n; ++t) {
    const TriangleId added = m.append_triangle(0_v, 1_v, 2_v);
    ref.resize(m.corner.size(), kNone);
    detail::subseg_slots(m).set(edge_of(added, 0), id_of(t));
    ref[edge_of(added, 0)] = id_of(t);
  }
  CHECK(matches(m, ref));
  CHECK_EQ(m.subseg.count(), n - 1);
  CHECK(m.subseg.bytes() < 16 * n);
}

// The values move to the dense array at a rehash where a quarter of the slots carry one and back
// to the table once fewer than an eighth do, and every reading agrees with the reference before
// and after each move and through the writes of a dense array (clears, truncation, renumbering).
TEST(the_values_move_between_table_and_dense_array_with_the_density) {
  Mesh m = slots_mesh(1);
  std::vector<SubsegmentId> ref(m.corner.size(), kNone);
  const auto append = [&](bool constrained) {
    const TriangleId t = m.append_triangle(0_v, 1_v, 2_v);
    ref.resize(m.corner.size(), kNone);
    if (!constrained) return;
    detail::subseg_slots(m).set(edge_of(t, 1), id_of(t));
    ref[edge_of(t, 1)] = id_of(t);
  };
  for (int i = 0; i < 2000; ++i) append(true);
  CHECK(m.subseg.is_dense());
  CHECK(matches(m, ref));
  for (int i = 0; i < 20000 && m.subseg.is_dense(); ++i) append(i % 16 == 0);
  CHECK(!m.subseg.is_dense());
  CHECK(8 * m.subseg.count() < m.subseg.size());
  CHECK(matches(m, ref));
  for (int i = 0; i < 60000 && !m.subseg.is_dense(); ++i) append(true);
  CHECK(m.subseg.is_dense());
  CHECK(matches(m, ref));
  // Writes while dense: every fourth value cleared, the last thousand slots dropped, odd ids gone.
  std::vector<EdgeRef> cleared;
  for (std::size_t e = 0; e < ref.size(); e += 4)
    if (ref[e] != kNone) cleared.push_back(EdgeRef{static_cast<std::uint32_t>(e)}), ref[e] = kNone;
  detail::subseg_slots(m).erase_all(cleared);
  CHECK(matches(m, ref));
  detail::subseg_slots(m).resize(ref.size() - 1000);
  ref.resize(ref.size() - 1000);
  CHECK(matches(m, ref));
  const auto renumber = [](SubsegmentId s) { return s % 2 == 1 ? SubsegmentId{kNone} : SubsegmentId{s / 2}; };
  detail::subseg_slots(m).remap(renumber);
  for (SubsegmentId& s : ref)
    if (s != kNone) s = renumber(s);
  CHECK(matches(m, ref));
  CHECK(m.subseg.holds(ref[edge_of(TriangleId{2}, 1)]));
  Mesh copy = m;
  CHECK(copy.subseg == m.subseg);
}
