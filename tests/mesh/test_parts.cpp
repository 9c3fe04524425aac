// hold_only and hold_all (mesh/parts.h): the side of a cut that stays holds only its own vertices
// and records while the part cut off is refined, and gets the mesh's ids back afterwards. Checked
// against a copy of the mesh taken before the cut: coordinates, kinds, markers and attributes by
// id, records field by field, and the triangles as vertex triples.
#include <algorithm>
#include <set>

#include "delaunay/triangulate.h"
#include "harness/check.h"
#include "mesh/operations.h"
#include "mesh/parts.h"
#include "mesh_checks.h"

using namespace deltri;
using namespace meshcheck;

namespace {

constexpr SubsegmentId kMark{0xFFFFFFFEu};

// A jittered 12 x 12 grid (every vertex a marker and two attributes of its own), its boundary as
// records, an interior chain of records across x = 0.5, a vertex no triangle uses (a duplicate)
// and a record on no edge: what only the mesh holds, neither side of the cut.
Mesh grid_with_records() {
  Mesh m;
  std::uint64_t state = 99;
  const auto jitter = [&] {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return (static_cast<double>(state >> 11) * 0x1p-53 - 0.5) * 0.02;
  };
  for (int i = 0; i < 12; ++i)
    for (int j = 0; j < 12; ++j) {
      const bool edge = i == 0 || j == 0 || i == 11 || j == 11;
      m.add_vertex({i / 11.0 + (edge ? 0.0 : jitter()), j / 11.0 + (edge ? 0.0 : jitter())}, VertexKind::Input);
    }
  delaunay_triangulate(m, DelaunayAlgorithm::DivideAndConquer, 1);
  m.enable_subsegments();
  m.marker.resize(m.vertex_count());
  m.num_attributes = 2;
  m.attributes.resize(2 * static_cast<std::size_t>(m.vertex_count()));
  for (VertexId v{0}; v < m.vertex_count(); ++v) {
    m.marker[v] = static_cast<int>(7 * v + 1);
    m.attributes[2 * v] = v + 0.25;
    m.attributes[2 * v + 1] = -1.0 * v;
  }
  const auto add_record = [&](EdgeRef e) {
    const SubsegmentId id = static_cast<SubsegmentId>(m.subsegments.size());
    m.subsegments.push_back({m.org(e), m.dest(e), static_cast<int>(id) + 3, 1000u + id});
    m.set_subsegment(e, id);
  };
  for (EdgeRef e{0}; e < m.corner.size(); ++e)
    if (m.corner[e] != kNone && m.link[e] == kNone) add_record(e);
  for (EdgeRef e{0}; e < m.corner.size(); ++e) {
    // Edges of the row j = 5 (vertex 12 i + 5), crossing the cut at x = 0.5.
    if (m.corner[e] == kNone || m.link[e] == kNone || m.subseg.has(e)) continue;
    const VertexId a = m.org(e), b = m.dest(e);
    if (a % 12 == 5 && b == a + 12) add_record(e);
  }
  m.add_vertex({0.5, 0.5}, VertexKind::Duplicate);
  m.marker.push_back(12345);
  m.attributes.insert(m.attributes.end(), {9.0, 9.5});
  m.subsegments.push_back({0_v, 1_v, 77, 7777});
  return m;
}

std::vector<std::uint8_t> right_of_half(const Mesh& m) {
  std::vector<std::uint8_t> moves(m.triangle_slots(), 0);
  for (TriangleId t{0}; t < m.triangle_slots(); ++t) {
    const auto [a, b, c] = m.corner_points(t);
    moves[t] = a.x + b.x + c.x > 1.5;
  }
  return moves;
}

bool same_record(const Subsegment& a, const Subsegment& b) {
  return a.a == b.a && a.b == b.b && a.marker == b.marker && a.segment == b.segment;
}

}  // namespace

TEST(the_side_that_stays_holds_only_its_own_and_gets_its_ids_back) {
  Mesh m = grid_with_records();
  const Mesh before = m;
  const std::vector<std::uint8_t> moves = right_of_half(m);
  std::set<std::uint32_t> stays;  // the corners of the triangles that stay, counted independently
  for (TriangleId t{0}; t < m.triangle_slots(); ++t)
    if (!moves[t])
      for (VertexId v : m.corners(t)) stays.insert(v);
  CutOff cut = cut_off(m, moves, kMark, {});
  Held held = hold_only(m, cut, {});

  CHECK_EQ(held.whole_vertices, before.vertex_count());
  CHECK_EQ(held.whole_records, before.subsegments.size());
  CHECK(std::vector<std::uint32_t>(held.vertices.begin(), held.vertices.end()) ==
        std::vector<std::uint32_t>(stays.begin(), stays.end()));
  CHECK_EQ(m.vertex_count(), held.vertices.size());
  CHECK_EQ(m.marker.size(), held.vertices.size());
  CHECK_EQ(m.attributes.size(), 2 * held.vertices.size());
  CHECK(held.rest_vertices == std::vector<VertexId>{VertexId{before.vertex_count() - 1}});
  CHECK(held.rest_records == std::vector<SubsegmentId>{static_cast<SubsegmentId>(before.subsegments.size() - 1)});
  CHECK(m.subsegments.size() < before.subsegments.size() - 1);
  std::size_t seam_marks = 0;
  for (TriangleId t{0}; t < m.triangle_slots(); ++t) {
    if (!m.is_live(t)) continue;
    for (unsigned i = 0; i < 3; ++i) {
      const EdgeRef e = edge_of(t, i);
      const VertexId w = held.vertices[m.corner[e]];
      CHECK(m.point(m.corner[e]) == before.point(w));
      CHECK_EQ(m.marker[m.corner[e]], before.marker[w]);
      CHECK_EQ(m.attributes[2 * m.corner[e] + 1], before.attributes[2 * w + 1]);
      if (!m.subseg.has(e)) continue;
      if (m.subseg[e] == kMark) {
        ++seam_marks;
        continue;
      }
      const Subsegment& r = m.subsegments[m.subseg[e]];
      CHECK(same_record(before.subsegments[held.records[m.subseg[e]]],
                        {held.vertices[r.a], held.vertices[r.b], r.marker, r.segment}));
      CHECK((r.a == m.org(e) && r.b == m.dest(e)) || (r.b == m.org(e) && r.a == m.dest(e)));
    }
  }
  CHECK(seam_marks > 0);

  // What refinement would add: a vertex inside a triangle of the side, and a record.
  TriangleId t{0};
  while (!m.is_live(t)) ++t;
  const auto [a, b, c] = m.corners(t);
  const auto [pa, pb, pc] = m.corner_points(t);
  const Point centre{(pa.x + pb.x + pc.x) / 3, (pa.y + pb.y + pc.y) / 3};
  const VertexId v = m.add_vertex(centre, VertexKind::Free);
  m.marker[v] = -4;
  m.attributes[2 * v] = 0.5;
  split_triangle(m, edge_of(t, 0), v);
  m.subsegments.push_back({a, v, 55, 5555});
  const VertexId wa = held.vertices[a], wb = held.vertices[b], wc = held.vertices[c];

  hold_all(m, held, cut);
  const VertexId added{before.vertex_count()};
  CHECK_EQ(m.vertex_count(), before.vertex_count() + 1);
  CHECK(m.point(added) == centre);
  CHECK_EQ(m.marker[added], -4);
  CHECK_EQ(m.attributes[2 * added], 0.5);
  CHECK(same_record(m.subsegments.back(), {wa, added, 55, 5555}));
  const PartIds ids = append_part(m, cut, kMark);
  sew_cut(m, cut, ids, kMark);
  for (VertexId u{0}; u < before.vertex_count(); ++u) {
    CHECK(m.point(u) == before.point(u));
    CHECK(m.kind[u] == before.kind[u]);
    CHECK_EQ(m.marker[u], before.marker[u]);
    CHECK_EQ(m.attributes[2 * u], before.attributes[2 * u]);
    CHECK_EQ(m.attributes[2 * u + 1], before.attributes[2 * u + 1]);
  }
  for (SubsegmentId s{0}; s < before.subsegments.size(); ++s) CHECK(same_record(m.subsegments[s], before.subsegments[s]));
  // The triangles: the mesh's, with t split in three around the added vertex.
  std::vector<Triple> expected = triangle_set(before);
  Triple old{wa, wb, wc};
  std::rotate(old.begin(), std::min_element(old.begin(), old.end()), old.end());
  const auto at = std::find(expected.begin(), expected.end(), old);
  REQUIRE(at != expected.end());
  expected.erase(at);
  for (Triple n : {Triple{wa, wb, added}, Triple{wb, wc, added}, Triple{wc, wa, added}}) {
    std::rotate(n.begin(), std::min_element(n.begin(), n.end()), n.end());
    expected.push_back(n);
  }
  std::sort(expected.begin(), expected.end());
  CHECK(triangle_set(m) == expected);
  CHECK_EQ(all_faults(m), 0);
  // Every record on its edge again, on both sides.
  for (EdgeRef e{0}; e < m.corner.size(); ++e) {
    if (m.corner[e] == kNone || !m.subseg.has(e)) continue;
    CHECK(m.subseg[e] != kMark);
    const Subsegment& r = m.subsegments[m.subseg[e]];
    CHECK((r.a == m.org(e) && r.b == m.dest(e)) || (r.b == m.org(e) && r.a == m.dest(e)));
    if (m.link[e] != kNone) CHECK_EQ(m.subseg[m.link[e]], m.subseg[e]);
  }
}
